#include "checkout/submodules.h"

#include <fmt/format.h>

#include <map>

#include "checkout/remote_cache.h"
#include "checkout/resolve.h"
#include "core/error.h"
#include "core/fs.h"

namespace fs = std::filesystem;

namespace raygate::git {
namespace {

constexpr int kMaxDepth = 16;  // deeper nesting is a cycle, not a project layout

// .gitmodules of `commit` as a path -> URL map (URLs as written, maybe relative).
std::map<std::string, std::string> read_gitmodules(git_commit* commit, std::string_view where) {
  TreePtr tree;
  check(git_commit_tree(tree.out(), commit), fmt::format("reading a commit tree in {}", where));
  TreeEntryPtr entry;
  if (git_tree_entry_bypath(entry.out(), tree.get(), ".gitmodules") < 0) {
    git_error_clear();
    return {};
  }
  BlobPtr blob;
  check(git_blob_lookup(blob.out(), git_commit_owner(commit), git_tree_entry_id(entry.get())),
        fmt::format("reading .gitmodules in {}", where));
  // libgit2 parses config only from files; a private copy also keeps a symlinked .gitmodules
  // from pointing the parser anywhere else.
  TempDir scratch("raygate-gitmodules");
  const fs::path file = scratch.path() / "gitmodules";
  write_file_atomically(file,
                        std::string_view(static_cast<const char*>(git_blob_rawcontent(blob.get())),
                                         static_cast<std::size_t>(git_blob_rawsize(blob.get()))));
  ConfigPtr config;
  check(git_config_open_ondisk(config.out(), file.c_str()),
        fmt::format("parsing .gitmodules in {}", where));

  std::map<std::string, std::string> urls;
  ConfigIteratorPtr it;
  check(git_config_iterator_new(it.out(), config.get()),
        fmt::format("reading .gitmodules in {}", where));
  git_config_entry* item = nullptr;
  while (git_config_next(&item, it.get()) == 0) {
    const std::string_view key = item->name;
    const std::string_view prefix = "submodule.", suffix = ".path";
    if (key.size() <= prefix.size() + suffix.size() || key.rfind(prefix, 0) != 0 ||
        key.substr(key.size() - suffix.size()) != suffix) {
      continue;
    }
    const std::string name(key.substr(0, key.size() - suffix.size()));
    Buf url;
    if (git_config_get_string_buf(url.out(), config.get(), (name + ".url").c_str()) == 0) {
      urls[item->value] = url.str();
    } else {
      git_error_clear();
    }
  }
  return urls;
}

bool has_commit(git_repository* repo, const git_oid& id) {
  CommitPtr commit;
  if (git_commit_lookup(commit.out(), repo, &id) == 0) return true;
  git_error_clear();
  return false;
}

// The cached clone of `url`, fetched if it does not have `pin` yet.
RepositoryPtr clone_having(const fs::path& cache_dir, const std::string& url, const git_oid& pin,
                           const std::string& path, std::string_view where) {
  RepositoryPtr repo = open_cached_clone(cache_dir, url, Fetch::never);
  if (has_commit(repo.get(), pin)) return repo;
  repo = open_cached_clone(cache_dir, url, Fetch::always);
  if (has_commit(repo.get(), pin)) return repo;
  throw InfraError(fmt::format(
      "submodule '{}' of {} is pinned at {}, which {} does not have (was that commit pushed?)",
      path, where, to_hex(pin), url));
}

}  // namespace

void populate_submodules(const SubmoduleSource& source, git_commit* commit,
                         const std::vector<Gitlink>& gitlinks, const fs::path& dir, int depth) {
  if (gitlinks.empty()) return;
  if (depth >= kMaxDepth) {
    throw InfraError(
        fmt::format("submodules of {} nest deeper than {} levels", source.where, kMaxDepth));
  }
  const auto urls = read_gitmodules(commit, source.where);
  for (const Gitlink& link : gitlinks) {
    const auto found = urls.find(link.path);
    if (found == urls.end()) {
      throw InfraError(fmt::format("submodule '{}' of {} has no URL in .gitmodules at commit {}",
                                   link.path, source.where, to_hex(*git_commit_id(commit))));
    }
    const std::string url = resolve_relative_url(found->second, source.super_url);
    RepositoryPtr sub = clone_having(source.cache_dir, url, link.commit, link.path, source.where);
    CommitPtr pinned = lookup_commit(sub.get(), link.commit, url);
    const fs::path sub_dir = dir / link.path;
    const auto nested = write_commit_tree(sub.get(), pinned.get(), sub_dir, url);
    populate_submodules(SubmoduleSource{source.cache_dir, url, url}, pinned.get(), nested, sub_dir,
                        depth + 1);
  }
}

}  // namespace raygate::git

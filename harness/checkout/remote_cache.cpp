#include "checkout/remote_cache.h"

#include <fmt/format.h>

#include "checkout/atomic_dir.h"
#include "checkout/file_lock.h"
#include "core/error.h"
#include "core/sha256.h"

namespace fs = std::filesystem;

namespace raygate {
namespace {

constexpr const char* kBranchSpec = "+refs/heads/*:refs/remotes/origin/*";
constexpr const char* kTagSpec = "+refs/tags/*:refs/tags/*";

// HEAD of the clone follows origin's default branch, so "HEAD~3" means what it means upstream.
// Detached, because the clone has no local branches to point at.
void point_head_at_default_branch(git_repository* repo, git_remote* remote,
                                  const std::string& url) {
  git::Buf branch;
  if (git_remote_default_branch(branch.out(), remote) < 0) {
    git_error_clear();  // an empty remote has no default branch; HEAD stays unborn
    return;
  }
  const std::string name = branch.str();
  const std::string heads = "refs/heads/";
  if (name.rfind(heads, 0) != 0) return;
  const std::string tracking = "refs/remotes/origin/" + name.substr(heads.size());
  git_oid id;
  if (git_reference_name_to_id(&id, repo, tracking.c_str()) < 0) {
    git_error_clear();
    return;
  }
  git::check(git_repository_set_head_detached(repo, &id),
             fmt::format("pointing HEAD of the clone of {} at {}", url, tracking));
}

void fetch_origin(git_repository* repo, const std::string& url) {
  git::RemotePtr remote;
  git::check(git_remote_lookup(remote.out(), repo, "origin"),
             fmt::format("reading the remote of the cached clone of {}", url));
  git_fetch_options options = GIT_FETCH_OPTIONS_INIT;
  options.prune = GIT_FETCH_PRUNE;
  git::check(git_remote_fetch(remote.get(), nullptr, &options, "raygate fetch"),
             fmt::format("fetching {} (check the URL and network access)", url));
  point_head_at_default_branch(repo, remote.get(), url);
}

void clone_into(const fs::path& dir, const std::string& url) {
  git::RepositoryPtr repo;
  git::check(git_repository_init(repo.out(), dir.c_str(), 1),
             fmt::format("creating a bare repository in {}", dir.string()));
  git::RemotePtr remote;
  git::check(git_remote_create_with_fetchspec(remote.out(), repo.get(), "origin", url.c_str(),
                                              kBranchSpec),
             fmt::format("adding remote {} to {}", url, dir.string()));
  git::check(git_remote_add_fetch(repo.get(), "origin", kTagSpec),
             fmt::format("configuring tag fetching for {}", url));
  fetch_origin(repo.get(), url);
}

git::RepositoryPtr open_bare(const fs::path& dir, const std::string& url) {
  git::RepositoryPtr repo;
  git::check(git_repository_open_bare(repo.out(), dir.c_str()),
             fmt::format("opening the cached clone of {} at {}", url, dir.string()));
  return repo;
}

}  // namespace

bool is_url(std::string_view location) {
  if (location.find("://") != std::string_view::npos) return true;
  const auto colon = location.find(':');
  return colon != std::string_view::npos && colon > 0 &&
         location.substr(0, colon).find('/') == std::string_view::npos;
}

fs::path clone_cache_path(const fs::path& cache_dir, std::string_view url) {
  return cache_dir / "repos" / sha256_hex(url).substr(0, 16);
}

std::string resolve_relative_url(std::string_view url, std::string_view base) {
  if (url.rfind("./", 0) != 0 && url.rfind("../", 0) != 0) return std::string(url);
  const std::string original(url);
  std::string out(base);
  while (out.size() > 1 && out.back() == '/') out.pop_back();
  const auto scheme = out.find("://");
  char joiner = '/';
  for (;;) {
    if (url.rfind("./", 0) == 0) {
      url.remove_prefix(2);
    } else if (url.rfind("../", 0) == 0) {
      url.remove_prefix(3);
      const auto cut = out.find_last_of("/:");
      if (cut == std::string::npos || (scheme != std::string::npos && cut <= scheme + 2)) {
        throw UsageError(fmt::format("submodule URL '{}' climbs above '{}'", original, base));
      }
      // "host:repo" loses "repo" but keeps the ':' that separates host and path.
      joiner = out[cut] == ':' ? ':' : '/';
      out.resize(cut);
    } else {
      break;
    }
  }
  out.push_back(joiner);
  out += url;
  return out;
}

git::RepositoryPtr open_cached_clone(const fs::path& cache_dir, const std::string& url,
                                     Fetch fetch) {
  const fs::path dir = clone_cache_path(cache_dir, url);
  std::error_code ec;
  if (fetch == Fetch::never && fs::is_directory(dir, ec)) return open_bare(dir, url);

  FileLock lock(lock_path_for(dir));
  if (fs::is_directory(dir, ec)) {
    git::RepositoryPtr repo = open_bare(dir, url);
    if (fetch == Fetch::always) fetch_origin(repo.get(), url);
    return repo;
  }
  build_directory_atomically(dir, [&](const fs::path& temp) { clone_into(temp, url); });
  return open_bare(dir, url);
}

}  // namespace raygate

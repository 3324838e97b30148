#include "checkout/repository.h"

#include <fmt/format.h>
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <optional>

#include "checkout/atomic_dir.h"
#include "checkout/describe.h"
#include "checkout/file_lock.h"
#include "checkout/remote_cache.h"
#include "checkout/resolve.h"
#include "checkout/safe_directory.h"
#include "checkout/submodules.h"
#include "checkout/tree_stamp.h"
#include "checkout/tree_writer.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/sanitize.h"

namespace fs = std::filesystem;

namespace raygate {
namespace {

[[noreturn]] void throw_refused(const fs::path& path, const std::string& root) {
  struct stat info {};
  std::string owner = "another user";
  if (::stat(root.c_str(), &info) == 0) {
    const passwd* user = ::getpwuid(info.st_uid);
    owner = fmt::format("uid {}{}", info.st_uid,
                        user != nullptr ? fmt::format(" ({})", user->pw_name) : "");
  }
  const std::string asked = path.string() == root ? "" : " (holding " + path.string() + ")";
  throw UsageError(fmt::format(
      "git refuses the repository {}{}: it is owned by {}, not by the user running raygate "
      "(uid {}), and git's ownership check (safe.directory) does not trust it; if you trust it, "
      "run: git config --global --add safe.directory {}",
      root, asked, owner, ::getuid(), root));
}

git::RepositoryPtr open_local(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    throw UsageError(fmt::format(
        "repository {} does not exist; give --repo a repository path or URL", path.string()));
  }
  git::RepositoryPtr repo;
  const int rc = open_repository_as_git_does(repo, path);
  if (const auto root = refused_for_ownership(path, rc)) throw_refused(path, *root);
  if (rc == GIT_ENOTFOUND) {
    throw UsageError(fmt::format(
        "{} is not in a git repository; give --repo a repository path or URL", path.string()));
  }
  git::check(rc, fmt::format("opening repository {}", path.string()));
  return repo;
}

constexpr const char* kNoTree = "not materialized yet";

// Why the cached tree at `dir` cannot be reused, or nullopt when it can: it is missing, has no
// stamp (made by a raygate that wrote none), a stamp of an older layout, or a file the checkout
// wrote was edited or removed since (tree_stamp.h).
std::optional<std::string> cached_tree_problem(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return kNoTree;
  std::ifstream in(stamp_path_for(dir), std::ios::binary);
  if (!in) return "it has no stamp to verify it by";
  const std::string stamp((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (stamp_is_outdated(stamp)) {
    return "it was written by an older raygate, whose checkout could leave binary files empty";
  }
  if (auto difference = stamp_difference(dir, stamp)) {
    return *difference + " since it was checked out";
  }
  return std::nullopt;
}

// Moves a rejected tree out of the way and deletes it. Renamed first, under the temporary prefix
// build_directory_atomically clears, so a crash half way through deleting leaves no partial
// tree under the final name.
void discard_tree(const fs::path& dir) {
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(dir, ec))) return;
  std::string name = ".";  // appended, not "." + ...: GCC 12 warns falsely (-Wrestrict) on that
  name += dir.filename().string();
  name += ".tmp-discarded";
  const fs::path aside = dir.parent_path() / name;
  fs::remove_all(aside, ec);
  if (std::rename(dir.c_str(), aside.c_str()) != 0) {
    throw InfraError(fmt::format("cannot move the stale worktree {} aside: {}", dir.string(),
                                 std::strerror(errno)));
  }
  fs::remove_all(aside, ec);
}

// A URL libgit2 has no transport for is the user's to fix (exit 2), not a fetch that failed (3):
// git's remote helpers (`ext::cmd`, `fd::`) and schemes other than libgit2's.
void check_url_transport(const std::string& location) {
  const std::size_t helper = location.find("::");
  if (helper != std::string::npos &&
      location.substr(0, helper).find_first_of("/:") == std::string::npos) {
    throw UsageError(fmt::format(
        "repository {}: git's remote helpers ({}::) are not supported; give a path, or an "
        "https, ssh, git or file URL",
        location, location.substr(0, helper)));
  }
  const std::size_t scheme = location.find("://");
  if (scheme == std::string::npos) return;  // scp-like: user@host:path
  const std::string name = location.substr(0, scheme);
  for (const char* known : {"http", "https", "ssh", "git", "file", "git+ssh", "ssh+git"}) {
    if (name == known) return;
  }
  throw UsageError(fmt::format(
      "repository {}: no way to fetch a {}:// URL; give a path, or an https, ssh, git or file URL",
      location, name));
}

}  // namespace

Repository Repository::open(const std::string& location, const fs::path& cache_dir) {
  Repository out;
  out.cache_dir_ = fs::absolute(cache_dir);
  if (is_url(location)) {
    check_url_transport(location);
    out.repo_ = open_cached_clone(out.cache_dir_, location, Fetch::always);
    out.where_ = location;
    out.url_base_ = location;
    out.fallback_prefix_ = "origin/";
  } else {
    out.repo_ = open_local(fs::absolute(location));
    out.url_base_ = repository_root(out.repo_.get());  // what "../sub" is relative to
    out.where_ = out.url_base_;
  }
  return out;
}

Revision Repository::resolve(const std::string& revspec) const {
  git::ResolvedCommit found = git::resolve_commit(repo_.get(), revspec, where_, fallback_prefix_);
  return git::describe_commit(found.commit.get(), revspec, std::move(found.ref_name));
}

Worktree Repository::checkout(const std::string& revspec) const {
  return materialize(resolve(revspec));
}

fs::path Repository::worktree_path(const std::string& sha) const {
  return cache_dir_ / "worktrees" / sha;
}

git::CommitPtr Repository::commit_of(const Revision& revision) const {
  git_oid id;
  if (revision.sha.size() != GIT_OID_HEXSZ || git_oid_fromstr(&id, revision.sha.c_str()) < 0) {
    throw UsageError(fmt::format("'{}' is not a full commit sha", revision.sha));
  }
  return git::lookup_commit(repo_.get(), id, where_);
}

Worktree Repository::materialize(const Revision& revision) const {
  const fs::path final_path = worktree_path(revision.sha);
  if (cached_tree_problem(final_path)) {
    git::CommitPtr commit = commit_of(revision);  // a bad sha is refused before any file is made
    FileLock lock(lock_path_for(final_path));
    // Another process may have built it meanwhile; otherwise say why it is rebuilt.
    if (const auto problem = cached_tree_problem(final_path)) {
      if (*problem != kNoTree) {
        // The problem names a file of the tree: its bytes are the commit's, not for a terminal.
        fmt::print(stderr, "note: recreating the cached worktree {}: {}\n", final_path.string(),
                   terminal_text(*problem));
      }
      discard_tree(final_path);
      build_directory_atomically(final_path, [&](const fs::path& temp) {
        const auto gitlinks = git::write_commit_tree(repo_.get(), commit.get(), temp, where_);
        git::populate_submodules({cache_dir_, url_base_, where_}, commit.get(), gitlinks, temp);
        // Written before the rename publishes the tree: a published tree always has its stamp.
        write_file_atomically(stamp_path_for(final_path), tree_stamp(temp));
      });
    }
  }
  return worktree_of(final_path, revision);
}

std::string Repository::how_unordered(const Revision& good, const Revision& bad) const {
  git_oid good_id, bad_id;
  git_oid_fromstr(&good_id, good.sha.c_str());
  git_oid_fromstr(&bad_id, bad.sha.c_str());
  const std::string doing = fmt::format("relating {} and {} in {}", good.sha, bad.sha, where_);
  if (git::check(git_graph_descendant_of(repo_.get(), &good_id, &bad_id), doing) == 1) {
    return fmt::format("it is newer, a descendant of {} (were the two swapped?)", bad.short_sha);
  }
  const std::optional<Revision> base = merge_base(good.sha, bad.sha);
  if (!base) return "the two have no commit in common (unrelated histories)";
  return fmt::format("the two diverged after {} {}", base->short_sha, base->subject);
}

std::vector<std::string> Repository::parents(const Revision& revision) const {
  const git::CommitPtr commit = commit_of(revision);
  std::vector<std::string> shas;
  for (unsigned i = 0; i < git_commit_parentcount(commit.get()); ++i) {
    shas.push_back(git::to_hex(*git_commit_parent_id(commit.get(), i)));
  }
  return shas;
}

std::optional<Revision> Repository::merge_base(const std::string& a, const std::string& b) const {
  const Revision first = resolve(a);
  const Revision second = resolve(b);
  git_oid ids[2];
  git_oid_fromstr(&ids[0], first.sha.c_str());
  git_oid_fromstr(&ids[1], second.sha.c_str());
  git_oid base;
  const int rc = git_merge_base(&base, repo_.get(), &ids[0], &ids[1]);
  if (rc == GIT_ENOTFOUND) {
    git_error_clear();
    return std::nullopt;
  }
  git::check(rc, fmt::format("finding the merge base of '{}' and '{}' in {}", a, b, where_));
  git::CommitPtr commit = git::lookup_commit(repo_.get(), base, where_);
  return git::describe_commit(commit.get(), git::to_hex(base), "");
}

std::vector<Revision> Repository::first_parent_history(const std::string& good,
                                                       const std::string& bad) const {
  // A shallow clone's history stops where it was cut, and libgit2 1.5 walks it into "object not
  // found" (exit 3; a sweep), leaking in that error path. Bisect needs the whole history: said
  // before any walk, as the checkout's depth to change.
  if (git_repository_is_shallow(repo_.get()) == 1) {
    throw UsageError(fmt::format(
        "{} is a shallow clone: bisect needs the whole history between '{}' and '{}'; fetch it "
        "(git fetch --unshallow, or fetch-depth: 0 in actions/checkout) and bisect again",
        where_, good, bad));
  }
  return walk_first_parents(good, bad);
}

std::vector<Revision> Repository::walk_first_parents(const std::string& good,
                                                     const std::string& bad) const {
  const Revision from = resolve(good);
  const Revision to = resolve(bad);
  if (from.sha == to.sha) return {};
  git_oid from_id, to_id;
  git_oid_fromstr(&from_id, from.sha.c_str());
  git_oid_fromstr(&to_id, to.sha.c_str());
  const std::string doing =
      fmt::format("walking history from '{}' to '{}' in {}", good, bad, where_);
  if (git::check(git_graph_descendant_of(repo_.get(), &to_id, &from_id), doing) != 1) {
    throw UsageError(
        fmt::format("'{}' ({}) is not an ancestor of '{}' ({}) in {}: {}; the good "
                    "revision must be older than the bad one, on its history",
                    good, from.short_sha, bad, to.short_sha, where_, how_unordered(from, to)));
  }
  git::RevwalkPtr walk;
  git::check(git_revwalk_new(walk.out(), repo_.get()), doing);
  git::check(git_revwalk_sorting(walk.get(), GIT_SORT_TOPOLOGICAL | GIT_SORT_REVERSE), doing);
  git::check(git_revwalk_simplify_first_parent(walk.get()), doing);
  git::check(git_revwalk_push(walk.get(), &to_id), doing);
  git::check(git_revwalk_hide(walk.get(), &from_id), doing);

  std::vector<Revision> history;
  git_oid id;
  int rc = 0;
  while ((rc = git_revwalk_next(&id, walk.get())) == 0) {
    git::CommitPtr commit = git::lookup_commit(repo_.get(), id, where_);
    history.push_back(git::describe_commit(commit.get(), git::to_hex(id), ""));
  }
  if (rc != GIT_ITEROVER) git::check(rc, doing);
  return history;
}

}  // namespace raygate

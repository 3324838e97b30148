// The checkout stage (DESIGN.md §2): a repository named by --repo, its revisions resolved to
// commits, and any commit materialised as a worktree in raygate's cache, never disturbing the
// user's own checkout (its HEAD, index, refs and files are only ever read).
//
// Cache layout under the caller's cache directory:
//   repos/<hash of URL>   bare clones of --repo URLs and of submodule URLs
//   worktrees/<sha>       one complete, read-only-by-convention tree per commit, submodules in
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "checkout/git_handle.h"
#include "checkout/worktree.h"

namespace raygate {

// Not thread-safe (one libgit2 repository handle); separate processes may share a cache.
class Repository {
 public:
  // `location` is a local path (opened in place; a subdirectory finds its repository like git
  // does) or a URL (cloned bare into the cache once, fetched on every later open; file:// works
  // offline). Throws UsageError when a path is not in a repository, InfraError when git fails.
  static Repository open(const std::string& location, const std::filesystem::path& cache_dir);

  // Any revspec: branch, tag (annotated ones peeled), full or short sha, HEAD~3, origin/main.
  // In a clone, a bare branch name also finds origin/<name>. Unknown: UsageError listing the
  // branches and tags.
  Revision resolve(const std::string& revspec) const;

  // resolve() then materialize().
  Worktree checkout(const std::string& revspec) const;

  // The commit's files, submodules included, in <cache>/worktrees/<sha>: built atomically on
  // first use, reused as they are afterwards.
  Worktree materialize(const Revision& revision) const;

  // The best common ancestor, or nothing for unrelated histories.
  std::optional<Revision> merge_base(const std::string& a, const std::string& b) const;

  // Commits after `good` up to and including `bad` along first parents, oldest first: the
  // candidates bisect steps through; empty when both name the same commit. UsageError unless
  // `good` is an ancestor of `bad`, saying how they relate instead (`good` is the newer one,
  // they are unrelated, or they diverged).
  std::vector<Revision> first_parent_history(const std::string& good, const std::string& bad) const;

  // The full shas of `revision`'s parents, first parent first (two or more: a merge).
  std::vector<std::string> parents(const Revision& revision) const;

  // The repository as the user named it, for messages.
  const std::string& location() const { return where_; }
  // <cache>/worktrees/<sha>, whether or not it exists yet.
  std::filesystem::path worktree_path(const std::string& sha) const;

 private:
  Repository() = default;
  git::CommitPtr commit_of(const Revision& revision) const;
  // Why `good` is not an ancestor of `bad`, for first_parent_history's message.
  std::string how_unordered(const Revision& good, const Revision& bad) const;
  // first_parent_history's walk, in a repository that is not shallow.
  std::vector<Revision> walk_first_parents(const std::string& good, const std::string& bad) const;

  git::Library library_;  // declared first: libgit2 must outlive the handles below
  git::RepositoryPtr repo_;
  std::string where_;            // the path or URL, in messages
  std::string url_base_;         // relative submodule URLs resolve against this
  std::string fallback_prefix_;  // "origin/" in a cached clone, where branches are remote refs
  std::filesystem::path cache_dir_;
};

}  // namespace raygate

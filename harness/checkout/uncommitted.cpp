// Worktree records for trees raygate did not check out itself (--worktree PATH).
#include <fmt/format.h>

#include "checkout/describe.h"
#include "checkout/git_handle.h"
#include "checkout/safe_directory.h"
#include "checkout/worktree.h"
#include "core/error.h"

namespace fs = std::filesystem;

namespace raygate {
namespace {

bool has_changes(git_repository* repo, const std::string& where) {
  git_status_options options = GIT_STATUS_OPTIONS_INIT;
  options.show = GIT_STATUS_SHOW_INDEX_AND_WORKDIR;
  // No GIT_STATUS_OPT_UPDATE_INDEX: looking must not write the user's index.
  options.flags = GIT_STATUS_OPT_INCLUDE_UNTRACKED | GIT_STATUS_OPT_EXCLUDE_SUBMODULES;
  git::StatusListPtr status;
  git::check(git_status_list_new(status.out(), repo, &options),
             fmt::format("reading the status of {}", where));
  return git_status_list_entrycount(status.get()) > 0;
}

Worktree unknown_tree(const fs::path& path) {
  Worktree out;
  out.path = path;
  out.sha = "uncommitted";
  out.short_sha = "uncommitted";
  out.dirty = true;
  return out;
}

}  // namespace

Worktree worktree_of(const fs::path& path, const Revision& revision) {
  return {revision, path, false};
}

Worktree describe_uncommitted_worktree(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path);
  if (!fs::is_directory(absolute, ec)) {
    throw UsageError(fmt::format("worktree {} is not a directory", absolute.string()));
  }
  git::Library library;
  git::RepositoryPtr repo;
  if (open_repository_as_git_does(repo, absolute) < 0 || git_repository_is_bare(repo.get())) {
    git_error_clear();
    return unknown_tree(absolute);
  }
  git::ObjectPtr head;
  if (git_revparse_single(head.out(), repo.get(), "HEAD^{commit}") < 0) {
    git_error_clear();  // unborn HEAD: nothing committed yet
    return unknown_tree(absolute);
  }
  const std::string where = absolute.string();
  Revision revision = git::describe_commit(reinterpret_cast<git_commit*>(head.get()), "HEAD", "");
  Worktree out = worktree_of(absolute, revision);
  out.dirty = has_changes(repo.get(), where);
  return out;
}

}  // namespace raygate

// Writes a commit's files into a directory straight from the object database: no index, no
// HEAD, no working tree of the repository is read for paths or written, so the user's checkout
// cannot be disturbed. Modes follow git: executables 0755, symlinks as symlinks.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "checkout/git_handle.h"

namespace raygate::git {

// A submodule entry of a tree: the path it occupies and the commit it is pinned to.
struct Gitlink {
  std::string path;  // relative, '/'-separated
  git_oid commit;
};

// Writes `commit`'s tree under `dir` (existing, empty). Blob contents pass through git's
// to-worktree filters with attributes taken from that commit (eol conversion as git would).
// Each gitlink becomes an empty directory and is returned for the caller to fill. Tree entries
// that could escape `dir` ("..", ".git", names with '/') are refused with an InfraError.
std::vector<Gitlink> write_commit_tree(git_repository* repo, git_commit* commit,
                                       const std::filesystem::path& dir, std::string_view where);

}  // namespace raygate::git

// Opening a local repository under git's ownership rules (safe.directory), as git itself applies
// them: libgit2 1.5 trusts only a safe.directory value equal to the repository's path, while
// git also honours `*` (trust every repository) and an empty value (forget the values before it).
// CI jobs commonly run `git config --global --add safe.directory '*'` in containers whose
// checkout belongs to another user; raygate must accept what git accepts there.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "checkout/git_handle.h"

namespace raygate {

// git's verdict for `root` given the safe.directory values of the system, XDG and global config
// files, in the order git reads them: `*` or a value naming `root` trusts it, an empty value
// resets the verdict to "not trusted".
bool safe_directory_trusts(const std::vector<std::string>& values, const std::string& root);

// The safe.directory values of the configs git protects (system, XDG, global; never a
// repository's own config), lowest precedence first.
std::vector<std::string> protected_safe_directories();

// Where a repository's files are (its work tree, or its git dir when bare), without a trailing
// slash: the folder git's ownership check and safe.directory are about.
std::string repository_root(git_repository* repo);

// When `rc`, the code of opening `path`, is git's ownership check refusing a repository (libgit2
// 1.5 reports it as GIT_ENOTFOUND, later versions as GIT_EOWNER): that repository's root, the
// folder safe.directory must name (its work tree, or its git dir when bare). Asks once more with
// the check off to tell a refused repository from no repository; the check is restored at once.
std::optional<std::string> refused_for_ownership(const std::filesystem::path& path, int rc);

// git_repository_open_ext on `path` (searching upwards like git), and when libgit2's ownership
// check refused a repository that git's safe.directory rules trust, opened again with the check
// off for that one call. Returns libgit2's code (0 on success).
int open_repository_as_git_does(git::RepositoryPtr& repo, const std::filesystem::path& path);

}  // namespace raygate

// The records the checkout stage hands to the builder (DESIGN.md §2): which commit a revision
// named, and the directory holding that commit's files. Plain values: copy, compare, store.
#pragma once

#include <filesystem>
#include <string>

namespace raygate {

// One commit, as a revision named it.
struct Revision {
  std::string revision;     // as the user wrote it: "main", "v1.2", "HEAD~3", a sha
  std::string ref_name;     // the ref it named ("refs/heads/main"); empty for shas and expressions
  std::string sha;          // 40 hex digits
  std::string short_sha;    // shortest unambiguous prefix, at least 7 digits
  std::string subject;      // first line of the message
  std::string author;       // author name
  std::string commit_time;  // committer time, ISO-8601 with its UTC offset

  bool operator==(const Revision&) const = default;
};

// The source tree a build runs in: the commit it holds, and where. Outside a git repository its
// sha and short_sha are "uncommitted" and the rest of the commit is empty.
struct Worktree : Revision {
  std::filesystem::path path;
  bool dirty = false;  // the files may differ from `sha` (a --worktree with local changes)

  bool operator==(const Worktree&) const = default;
};

// A worktree record for `path` holding the commit `revision` (dirty = false).
Worktree worktree_of(const std::filesystem::path& path, const Revision& revision);

// For `--worktree PATH`, a tree the user may have edited. Inside a git repository: HEAD's
// commit, dirty when git_status reports any change (untracked files count, ignored do not).
// Elsewhere, or on an unborn HEAD: sha "uncommitted", dirty = true. Never writes to the repository.
Worktree describe_uncommitted_worktree(const std::filesystem::path& path);

}  // namespace raygate

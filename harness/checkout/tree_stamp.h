// A cheap fingerprint of a materialized worktree, so a cached tree is verified before reuse: an
// edited, deleted or emptied tree would otherwise be measured and recorded under its clean
// commit. The stamp lists every file the checkout wrote with (size, mtime, mode) and lives
// beside the tree, not in it. Verifying is one lstat per listed file, no reading of contents:
// fast enough to run on every use of a large repository (docs/checkout.md has the numbers).
// Files that appear later are not compared, because in-tree builds (make-nff builds in {src})
// add their outputs there; a file the checkout wrote that is changed or gone is a difference.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace raygate {

// "<parent>/.<name>.stamp" for the tree at `dir`.
std::filesystem::path stamp_path_for(const std::filesystem::path& dir);

// The stamp text of every regular file and symlink under `root` (symlinks not followed).
std::string tree_stamp(const std::filesystem::path& root);

// Whether `stamp` is of an older layout than this raygate writes: its tree was written by an
// older checkout and is rewritten rather than trusted.
bool stamp_is_outdated(const std::string& stamp);

// What differs between `root` and the stamp text `stamp`, e.g. "src/a.cpp was modified";
// nullopt when every listed file is as it was. A malformed stamp is a difference too.
std::optional<std::string> stamp_difference(const std::filesystem::path& root,
                                            const std::string& stamp);

}  // namespace raygate

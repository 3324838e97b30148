// Replacing a whole directory so that a reader finds the old one or the new one, each complete,
// never a mix: the new contents are built in a temporary directory beside the old one (same
// file system), synced to disk, and swapped in with one rename. For sets of files that must
// agree with each other, such as goldens and the manifest that holds their sha256: writing them
// in place left a truncated golden under a manifest naming the old hash when the disk filled.
#pragma once

#include <filesystem>
#include <functional>

namespace raygate {

// Builds the new `target` by calling `fill` on an empty temporary directory beside it
// ("<parent>/.<name>.new-XXXXXX"), syncs every file and folder in it, then swaps it in: with
// renameat2(RENAME_EXCHANGE) where the file system offers it, so `target` never disappears;
// else the old is renamed aside and the new into place. The old contents are then removed.
// When `fill` throws, or a sync or the swap fails, the temporary is removed, `target` is as it
// was, and the exception travels up (a WriteError names the file that could not be written).
// A `target` that is a symbolic link is resolved: the directory it points to is replaced.
void replace_directory(const std::filesystem::path& target,
                       const std::function<void(const std::filesystem::path&)>& fill);

// Fills `to` (an existing, empty directory) with `from`'s entries: regular files hard-linked
// (copied where the file system has no links), folders recreated, symbolic links copied. The
// start of a new version that changes a few files: links cost no space, and the old files are
// never written through them, only unlinked and replaced.
void link_tree(const std::filesystem::path& from, const std::filesystem::path& to);

// "<parent>/.<name>.new-": the prefix of replace_directory's temporaries, for code that lists a
// parent directory and must not take a half-built one for a real entry.
bool is_replacement_temporary(const std::filesystem::path& entry);

}  // namespace raygate

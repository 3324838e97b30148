// Cache entries that appear whole or not at all. A directory is built under a temporary name
// beside its final one and renamed into place when complete, so a directory with the final
// name is always complete, and a run killed half way leaves only a temporary that is never
// used and is deleted by the next run that builds the same entry.
#pragma once

#include <filesystem>
#include <functional>

namespace raygate {

// "<parent>/.<name>.lock": hold a FileLock on it while checking for or building `dir`.
std::filesystem::path lock_path_for(const std::filesystem::path& dir);

// Builds `final_path` by calling `fill` on an empty temporary directory beside it, then syncs
// and renames it into place. The caller holds the FileLock for `final_path`, so any leftover
// temporary of the same entry belongs to a dead run: those are removed first. If `fill`
// throws, its temporary is removed and the exception propagates.
void build_directory_atomically(const std::filesystem::path& final_path,
                                const std::function<void(const std::filesystem::path&)>& fill);

}  // namespace raygate

// Submodules as `git submodule update --init --recursive` would leave them, without touching
// any repository's working tree: each gitlink directory of a written tree is filled with the
// submodule's files at the pinned commit, read from the submodule's cached clone.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "checkout/git_handle.h"
#include "checkout/tree_writer.h"

namespace raygate::git {

struct SubmoduleSource {
  std::filesystem::path cache_dir;  // clones live in <cache_dir>/repos/
  std::string super_url;            // the superproject's URL or directory, for "../x" URLs
  std::string where;                // the superproject, for messages
};

// Fills every gitlink of `commit` (already written under `dir`) from the URL its .gitmodules
// gives for that path, recursively. A clone is fetched only when it lacks a pinned commit.
void populate_submodules(const SubmoduleSource& source, git_commit* commit,
                         const std::vector<Gitlink>& gitlinks, const std::filesystem::path& dir,
                         int depth = 0);

}  // namespace raygate::git

// Scene preparation: the NFF text of a suite entry, generated once into a cache directory.
#pragma once

#include <filesystem>

#include "runner/suite.h"

namespace raygate {

// Writes <cache_dir>/<id>.nff (atomically) unless an identical file is already there, and
// returns its path. Generation is deterministic, so the file is a pure function of the entry.
std::filesystem::path prepare_scene(const SuiteScene& scene, const std::filesystem::path& cache_dir);

}  // namespace raygate

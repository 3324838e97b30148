// Scene preparation: the NFF text of a suite entry, generated once into a cache directory.
#pragma once

#include <filesystem>

#include "adapter/adapter.h"
#include "runner/suite.h"

namespace raygate {

// Writes <cache_dir>/<id>.nff (atomically) unless an identical file is already there, and
// returns its path. Generation is deterministic, so the file is a pure function of the entry.
std::filesystem::path prepare_scene(const SuiteScene& scene,
                                    const std::filesystem::path& cache_dir);

// Converts a prepared NFF file for tracers that read another format (scenes/writers): writes
// <cache_dir>/<stem>.<pov|obj|pbrt> (with a .mtl beside an .obj) atomically and returns the main
// file. A scene the writers cannot express is a UsageError naming the file.
std::filesystem::path prepare_converted_scene(const std::filesystem::path& nff, SceneFormat format,
                                              const std::filesystem::path& cache_dir);

}  // namespace raygate

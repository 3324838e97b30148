#include "runner/scene_files.h"

#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/fs.h"
#include "spd.h"

namespace raygate {

std::filesystem::path prepare_scene(const SuiteScene& scene,
                                    const std::filesystem::path& cache_dir) {
  scenes::GenerateOptions options;
  if (scene.size != 0) options.size = scene.size;
  options.width = scene.width;
  options.height = scene.height;
  std::ostringstream text;
  try {
    scenes::generate(scene.scene, options, text);
  } catch (const std::invalid_argument& e) {
    throw UsageError(scene.id + ": " + e.what());
  }
  const std::filesystem::path path = cache_dir / (scene.id + ".nff");
  std::error_code ec;
  if (std::filesystem::exists(path, ec)) {
    try {
      if (read_file(path) == text.str()) return path;
    } catch (const UsageError&) {
      // unreadable cache entry: rewrite it below
    }
  }
  write_file_atomically(path, text.str());
  return path;
}

}  // namespace raygate

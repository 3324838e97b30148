#include "runner/scene_files.h"

#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "core/fs.h"
#include "core/path_component.h"
#include "nff/parser.h"
#include "spd.h"
#include "writers/scene_writers.h"

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
  const std::filesystem::path path = join_component(cache_dir, scene.id, "scene id", ".nff");
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

std::filesystem::path prepare_converted_scene(const std::filesystem::path& nff, SceneFormat format,
                                              const std::filesystem::path& cache_dir) {
  const std::optional<writers::OutputFormat> output =
      writers::parse_output_format(std::string(to_string(format)));
  if (!output)
    throw UsageError("no scene writer for format '" + std::string(to_string(format)) + "'");
  const std::filesystem::path out =
      cache_dir / (nff.stem().string() + "." + std::string(to_string(format)));
  try {
    const nff::Scene scene = nff::read_nff_file(nff.string());
    return writers::write_scene_files(scene, *output, out).front();
  } catch (const nff::ParseError& e) {
    throw UsageError(e.what());
  } catch (const std::invalid_argument& e) {
    throw UsageError(nff.string() + ": cannot convert to " + std::string(to_string(format)) + ": " +
                     e.what());
  }
}

}  // namespace raygate

// Format names and writing converted scenes to files (scene_writers.h).
#include "writers/scene_writers.h"

#include <sstream>
#include <stdexcept>

#include "core/fs.h"
#include "writers/scene_geometry.h"

namespace raygate::writers {
namespace {

std::filesystem::path with_extension(const std::filesystem::path& path, const char* extension) {
  std::filesystem::path result = path;
  result.replace_extension(extension);
  return result;
}

}  // namespace

std::optional<OutputFormat> parse_output_format(std::string_view name) {
  if (name == "pov") return OutputFormat::pov;
  if (name == "obj") return OutputFormat::obj;
  if (name == "pbrt") return OutputFormat::pbrt;
  return std::nullopt;
}

std::string_view format_name(OutputFormat format) {
  switch (format) {
    case OutputFormat::pov: return "pov";
    case OutputFormat::obj: return "obj";
    case OutputFormat::pbrt: return "pbrt";
  }
  return "?";
}

std::vector<std::filesystem::path> write_scene_files(const nff::Scene& scene, OutputFormat format,
                                                     const std::filesystem::path& out,
                                                     const WriteOptions& options) {
  // Everything is converted before anything is written, so an error leaves no file behind.
  std::ostringstream main;
  std::vector<std::filesystem::path> written{out};
  std::ostringstream mtl;
  switch (format) {
    case OutputFormat::pov: write_pov(scene, main); break;
    case OutputFormat::obj: {
      const std::filesystem::path mtl_path = with_extension(out, ".mtl");
      if (mtl_path == out)
        throw std::invalid_argument("the OBJ file must not end in .mtl: " + out.string());
      write_obj(scene, main, mtl_path.filename().string(), options);
      write_mtl(scene, mtl);
      written.push_back(mtl_path);
      break;
    }
    case OutputFormat::pbrt:
      write_pbrt(scene, main, with_extension(out.filename(), ".exr").string(), options);
      break;
  }
  // The MTL goes first: once the OBJ exists, what it refers to exists too.
  if (written.size() > 1) write_file_atomically(written[1], mtl.str());
  write_file_atomically(out, main.str());
  return written;
}

}  // namespace raygate::writers

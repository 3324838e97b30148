#include "pipeline/scene_commands.h"

#include <fmt/core.h>

#include <sstream>
#include <stdexcept>

#include "core/error.h"
#include "nff/parser.h"
#include "pipeline/output_failures.h"
#include "spd.h"
#include "writers/scene_writers.h"

namespace raygate {
namespace {

void parse_resolution(const std::string& text, scenes::GenerateOptions& options) {
  if (text.empty()) return;
  long long w = 0;  // wider than a side may be, so 16x99999999999 is a side out of range
  long long h = 0;
  char x = 0;
  std::istringstream in(text);
  // >> skips space, so " 10x10" and "10 x 10" read as 10x10.
  const bool spaced = text.find_first_of(" \t\n\r\v\f") != std::string::npos;
  if (spaced || !(in >> w >> x >> h) || x != 'x' || !in.eof()) {
    throw UsageError("--resolution: expected WIDTHxHEIGHT (e.g. 128x128), found '" + text + "'");
  }
  // 0 in the generator keeps the scene's own; given, it is a mistake.
  if (w < 1 || h < 1 || w > 16384 || h > 16384) {
    throw UsageError(fmt::format("--resolution {}: each side must be in 1..16384", text));
  }
  options.width = static_cast<int>(w);
  options.height = static_cast<int>(h);
}

}  // namespace

nlohmann::json scene_list_json() {
  nlohmann::json scenes = nlohmann::json::array();
  for (const scenes::SceneGenerator& g : scenes::all_generators()) {
    nlohmann::json scene = {{"name", g.name}, {"description", g.description}};
    scene["default_size"] = g.uses_size ? nlohmann::json(g.default_size) : nlohmann::json(nullptr);
    scene["max_size"] = g.uses_size ? nlohmann::json(scenes::max_size(g)) : nlohmann::json(nullptr);
    scenes.push_back(scene);
  }
  return {{"scenes", scenes}};
}

std::string scene_list_text() {
  std::string out =
      fmt::format("{:<10} {:>7} {:>5}  {}\n", "scene", "default", "max", "description");
  for (const scenes::SceneGenerator& g : scenes::all_generators()) {
    out += fmt::format("{:<10} {:>7} {:>5}  {}\n", g.name,
                       g.uses_size ? std::to_string(g.default_size) : "-",
                       g.uses_size ? std::to_string(scenes::max_size(g)) : "-", g.description);
  }
  return out;
}

std::string generate_scene(const SceneRequest& request) {
  scenes::GenerateOptions options;
  options.size = request.size;
  if (request.tessellate > 0) {
    options.mode = scenes::OutputMode::tessellated;
    options.tessellation_resolution = request.tessellate;
  }
  parse_resolution(request.resolution, options);
  std::ostringstream text;
  try {
    scenes::generate(request.name, options, text);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  return text.str();
}

std::vector<std::filesystem::path> convert_scene(const ConvertRequest& request) {
  const std::optional<writers::OutputFormat> format = writers::parse_output_format(request.format);
  if (!format) {
    throw UsageError("--to: unknown format '" + request.format + "' (expected pov, obj or pbrt)");
  }
  // The converted files must not replace the scene they are made from (the fifth sweep: `-o` as
  // the input, a hard link to it, or `-o in.obj` whose MTL is the input, replaced it).
  std::vector<NamedFile> files{{"the input scene", request.input}, {"-o", request.output}};
  if (*format == writers::OutputFormat::obj && !request.output.empty() && request.output != "-") {
    files.push_back(
        {"-o's MTL file", std::filesystem::path(request.output).replace_extension(".mtl")});
  }
  check_distinct_files(files);
  try {
    const nff::Scene scene = nff::read_nff_file(request.input);
    const writers::WriteOptions options{request.segments};
    return writers::write_scene_files(scene, *format, request.output, options);
  } catch (const nff::ParseError& e) {
    throw UsageError(e.what());  // "path:line:col: expected ..., found ..."
  } catch (const std::invalid_argument& e) {
    throw UsageError(request.input + ": " + e.what());
  }
}

}  // namespace raygate

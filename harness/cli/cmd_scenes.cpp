// `raygate scenes list | generate | convert`: the SPD generators from the command line, and
// NFF scenes converted for other tracers (POV-Ray, OBJ, pbrt-v4; docs/scene-formats.md).
#include <fmt/core.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/console.h"
#include "core/error.h"
#include "core/fs.h"
#include "nff/parser.h"
#include "spd.h"
#include "writers/scene_writers.h"

namespace raygate::cli {
namespace {

struct ConvertArgs {
  std::string input;
  std::string format;
  std::string output;
  int segments = writers::WriteOptions{}.segments;
};

struct GenerateArgs {
  std::string name;
  std::optional<int> size;
  int tessellate = 0;  // 0: curves mode
  std::string resolution;
  std::string output;
};

void parse_resolution(const std::string& text, scenes::GenerateOptions& options) {
  if (text.empty()) return;
  int w = 0;
  int h = 0;
  char x = 0;
  std::istringstream in(text);
  if (!(in >> w >> x >> h) || x != 'x' || !in.eof()) {
    throw UsageError("--resolution: expected WIDTHxHEIGHT (e.g. 128x128), found '" + text + "'");
  }
  options.width = w;
  options.height = h;
}

nlohmann::json scenes_json() {
  nlohmann::json scenes = nlohmann::json::array();
  for (const scenes::SceneGenerator& g : scenes::all_generators()) {
    nlohmann::json scene = {{"name", g.name}, {"description", g.description}};
    scene["default_size"] = g.uses_size ? nlohmann::json(g.default_size) : nlohmann::json(nullptr);
    scene["max_size"] = g.uses_size ? nlohmann::json(scenes::max_size(g)) : nlohmann::json(nullptr);
    scenes.push_back(scene);
  }
  return {{"scenes", scenes}};
}

void run_list(const std::string& format) {
  if (format == "json") {
    fmt::print("{}\n", scenes_json().dump(1));
    return;
  }
  fmt::print("{:<10} {:>7} {:>5}  {}\n", "scene", "default", "max", "description");
  for (const scenes::SceneGenerator& g : scenes::all_generators()) {
    fmt::print("{:<10} {:>7} {:>5}  {}\n", g.name, g.uses_size ? std::to_string(g.default_size) : "-",
               g.uses_size ? std::to_string(scenes::max_size(g)) : "-", g.description);
  }
}

void run_generate(const GenerateArgs& args) {
  scenes::GenerateOptions options;
  options.size = args.size;
  if (args.tessellate > 0) {
    options.mode = scenes::OutputMode::tessellated;
    options.tessellation_resolution = args.tessellate;
  }
  parse_resolution(args.resolution, options);
  std::ostringstream text;
  try {
    scenes::generate(args.name, options, text);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (args.output.empty() || args.output == "-") {
    std::cout << text.str();
    std::cout.flush();
    if (!std::cout) throw InfraError("cannot write the scene to standard output");
  } else {
    write_file_atomically(args.output, text.str());
  }
}

void run_convert(const ConvertArgs& args) {
  const std::optional<writers::OutputFormat> format = writers::parse_output_format(args.format);
  if (!format) {
    throw UsageError("--to: unknown format '" + args.format + "' (expected pov, obj or pbrt)");
  }
  try {
    const nff::Scene scene = nff::read_nff_file(args.input);
    const writers::WriteOptions options{args.segments};
    for (const auto& path : writers::write_scene_files(scene, *format, args.output, options)) {
      fmt::print("{}\n", path.string());
    }
  } catch (const nff::ParseError& e) {
    throw UsageError(e.what());  // "path:line:col: expected ..., found ..."
  } catch (const std::invalid_argument& e) {
    throw UsageError(args.input + ": " + e.what());
  }
}

void add_convert_command(CLI::App& scenes, int& exit_code) {
  auto args = std::make_shared<ConvertArgs>();
  CLI::App* convert = scenes.add_subcommand(
      "convert", "Convert an NFF scene for another tracer: POV-Ray, OBJ + MTL, or pbrt-v4");
  convert->add_option("input", args->input, "NFF scene file")->required();
  convert->add_option("--to", args->format, "Output format: pov, obj or pbrt")->required();
  convert->add_option("-o,--output", args->output, "Output file (OBJ also writes OUT.mtl)")
      ->required();
  convert->add_option("--segments", args->segments,
                      "Facets around tessellated spheres and cones (OBJ; pbrt cones)")
      ->default_val(args->segments)
      ->check(CLI::Range(3, 1024));
  convert->callback([args, &exit_code] {
    run_convert(*args);
    exit_code = 0;
  });
}

}  // namespace

void add_scenes_command(CLI::App& app, int& exit_code) {
  CLI::App* scenes = app.add_subcommand(
      "scenes", "List, generate and convert SPD scenes (NFF; POV-Ray, OBJ, pbrt-v4)");
  scenes->require_subcommand(1);

  auto list_format = std::make_shared<std::string>();
  CLI::App* list =
      scenes->add_subcommand("list", "The 13 SPD scenes with default and largest size factors");
  add_format_option(*list, *list_format, {"text", "json"});
  list->callback([list_format, &exit_code] {
    run_list(*list_format);
    exit_code = 0;
  });

  auto args = std::make_shared<GenerateArgs>();
  CLI::App* generate = scenes->add_subcommand("generate", "Write one SPD scene as NFF");
  generate->add_option("name", args->name, "Scene name (see 'raygate scenes list')")->required();
  generate->add_option("-s,--size", args->size, "SPD size factor (default: the scene's own)");
  generate->add_option("-t,--tessellate", args->tessellate,
                       "Tessellate curved primitives into triangles at this resolution (SPD: 3)")
      ->expected(0, 1)
      ->default_str("3");
  generate->add_option("--resolution", args->resolution, "Image size written into the view, WxH");
  generate->add_option("-o,--output", args->output, "Output file (default: standard output)");
  generate->callback([args, &exit_code, generate] {
    if (generate->count("--tessellate") > 0 && args->tessellate == 0) args->tessellate = 3;
    run_generate(*args);
    exit_code = 0;
  });
  add_convert_command(*scenes, exit_code);
}

}  // namespace raygate::cli

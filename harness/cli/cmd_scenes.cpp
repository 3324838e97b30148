// `raygate scenes list | generate`: the SPD generators from the command line.
#include <fmt/core.h>

#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>

#include "cli/commands.h"
#include "core/error.h"
#include "core/fs.h"
#include "spd.h"

namespace raygate::cli {
namespace {

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

void run_list() {
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

}  // namespace

void add_scenes_command(CLI::App& app, int& exit_code) {
  CLI::App* scenes = app.add_subcommand("scenes", "List and generate the SPD scenes (NFF)");
  scenes->require_subcommand(1);

  scenes->add_subcommand("list", "The 13 SPD scenes with default and largest size factors")
      ->callback([&exit_code] {
        run_list();
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
}

}  // namespace raygate::cli

// `raygate scenes list | generate | convert`: the SPD generators from the command line, and
// NFF scenes converted for other tracers (pipeline/scene_commands.h).
#include <fmt/core.h>

#include <iostream>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/subcommand.h"
#include "core/error.h"
#include "core/fs.h"
#include "pipeline/scene_commands.h"

namespace raygate::cli {
namespace {

void run_generate(const SceneRequest& request, const std::string& output) {
  const std::string text = generate_scene(request);
  if (output.empty() || output == "-") {
    std::cout << text;  // a full standard output: main's check, exit 3
  } else {
    write_file_atomically(output, text);
  }
}

int run_convert(const ConvertRequest& request) {
  for (const auto& path : convert_scene(request)) fmt::print("{}\n", path.string());
  return 0;
}

int run_list(const std::string& format) {
  print_result(format, scene_list_json, scene_list_text);
  return 0;
}

void add_convert_command(CLI::App& scenes, int& exit_code) {
  const auto [convert, args] = add_subcommand<ConvertRequest>(
      scenes, "convert", "convert an NFF scene for another tracer: POV-Ray, OBJ + MTL, or pbrt-v4",
      run_convert, exit_code);
  convert->add_option("input", args->input, "NFF scene file")->required();
  convert->add_option("--to", args->format, "Output format: pov, obj or pbrt")->required();
  convert->add_option("-o,--output", args->output, "Output file (OBJ also writes OUT.mtl)")
      ->required()
      ->check(writable_file());
  add_bounded_option(*convert, "--segments", args->segments, 3, 1024,
                     "Facets around tessellated spheres and cones (OBJ; pbrt cones)");
}

}  // namespace

void add_scenes_command(CLI::App& scenes, int& exit_code) {
  scenes.require_subcommand(1);

  const auto [list, list_format] = add_subcommand<std::string>(
      scenes, "list", "the 13 SPD scenes with default and largest size factors", run_list,
      exit_code);
  add_format_option(*list, *list_format, {"text", "json"});

  auto args = std::make_shared<SceneRequest>();
  auto output = std::make_shared<std::string>();
  CLI::App* generate = scenes.add_subcommand("generate", "write one SPD scene as NFF");
  generate->add_option("name", args->name, "Scene name (see 'raygate scenes list')")->required();
  generate->add_option("-s,--size", args->size, "SPD size factor (default: the scene's own)");
  generate
      ->add_option("-t,--tessellate", args->tessellate,
                   "Tessellate curved primitives into triangles at this resolution (SPD: 3)")
      ->expected(0, 1)
      ->default_str("3")
      ->check(CLI::Validator([](const std::string& t) { return number_problem(t, true, 1, 64); },
                             "", ""));
  generate->add_option("--resolution", args->resolution, "Image size written into the view, WxH");
  generate->add_option("-o,--output", *output, "Output file (default: standard output)")
      ->check(writable_file());
  generate->callback([args, output, &exit_code, generate] {
    if (generate->count("--tessellate") > 0 && args->tessellate == 0) args->tessellate = 3;
    run_generate(*args, *output);
    exit_code = 0;
  });
  add_convert_command(scenes, exit_code);
}

}  // namespace raygate::cli

// raygate-baseline: the reference Whitted tracer every raygate measurement is normalized
// against (DESIGN.md §3, docs/baseline.md). Reads NFF, writes an image, optionally statistics.
// Exit codes: 0 ok, 1 an output could not be written, 2 usage error or unusable scene.
#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <iterator>
#include <map>
#include <string>

#include "baseline_version.h"
#include "image/file_output.h"
#include "image/image_writer.h"
#include "nff/parser.h"
#include "render/camera.h"
#include "render/render.h"
#include "render/stats_json.h"
#include "render/world.h"

namespace {

using raygate::render::Accel;
using raygate::render::Sampling;
using Clock = std::chrono::steady_clock;

constexpr int kExitOk = 0;
constexpr int kExitOutputFailed = 1;
constexpr int kExitUsage = 2;

struct Options {
  std::string scene_path;
  std::string output_path;
  std::string stats_path;
  Accel accel = Accel::none;
  Sampling sampling = Sampling::center;
  int max_depth = 5;
  bool print_time = false;
};

// CPU seconds (user + system) this process has used so far.
double process_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string version_line() {
  return fmt::format("raygate-baseline {} source-sha256:{}", raygate::baseline_build::kVersion,
                     raygate::baseline_build::kSourceSha256);
}

void add_options(CLI::App& app, Options& options) {
  app.set_version_flag("--version", version_line());
  app.add_option("scene", options.scene_path, "NFF scene file, or - to read standard input")
      ->required();
  app.add_option("-o,--output", options.output_path,
                 "image to write; the extension picks the format: .png, .ppm, .tga (8-bit), "
                 ".pfm (float)")
      ->required();
  const std::map<std::string, Accel> accels{{"none", Accel::none}, {"bbox", Accel::bbox}};
  app.add_option("--accel", options.accel,
                 "none: every ray against every primitive (the benchmark); bbox: a box test "
                 "per primitive first (the control)")
      ->transform(CLI::CheckedTransformer(accels));
  const std::map<std::string, Sampling> samplings{{"center", Sampling::center},
                                                  {"corners", Sampling::corners}};
  app.add_option("--sampling", options.sampling,
                 "center: one ray per pixel centre; corners: SPD's (W+1)x(H+1) corner rays")
      ->transform(CLI::CheckedTransformer(samplings));
  app.add_option("--stats", options.stats_path, "write ray counts and timings as JSON");
  app.add_flag("--print-time", options.print_time,
               "print 'raygate-baseline: in-process seconds S' (parse + prepare + render) on "
               "stdout, for harnesses that time the tracer by its own report");
  app.add_option("--depth", options.max_depth, "maximum ray-tree depth, eye ray = 1")
      ->check(CLI::Range(1, 64));
}

raygate::nff::Scene read_scene(const std::string& path) {
  if (path == "-") {
    const std::string text{std::istreambuf_iterator<char>(std::cin),
                           std::istreambuf_iterator<char>()};
    return raygate::nff::parse_nff(text, "<stdin>");
  }
  return raygate::nff::read_nff_file(path);
}

bool write_stats(const std::string& path, const raygate::render::RunReport& report,
                 std::string& error) {
  // The scene's path is in the report: a byte that is not UTF-8 is written as U+FFFD (it made
  // nlohmann throw, and the baseline abort, in a folder named in Latin-1).
  const nlohmann::json json = raygate::render::to_json(report);
  return raygate::write_file_replacing(
      path, json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n", error);
}

int run(const Options& options) {
  if (const std::string why = raygate::check_output_format(options.output_path); !why.empty()) {
    fmt::print(stderr, "raygate-baseline: {}\n", why);
    return kExitUsage;
  }
  raygate::render::RunReport report;
  report.version = raygate::baseline_build::kVersion;
  report.source_sha256 = raygate::baseline_build::kSourceSha256;
  report.scene = options.scene_path;
  report.sampling = options.sampling;
  report.accel = options.accel;
  report.max_depth = options.max_depth;

  const double cpu_start = process_cpu_seconds();
  const Clock::time_point parse_start = Clock::now();
  const raygate::nff::Scene scene = read_scene(options.scene_path);
  report.parse_seconds = seconds_since(parse_start);

  const Clock::time_point prepare_start = Clock::now();
  const raygate::render::Camera camera = raygate::render::make_camera(scene.view);
  const raygate::render::World world = raygate::render::build_world(scene);
  report.prepare_seconds = seconds_since(prepare_start);
  report.width = camera.width;
  report.height = camera.height;
  report.primitives = world.primitive_count();
  report.degenerate_primitives = world.degenerate_primitives;
  report.lights = world.lights.size();

  const Clock::time_point render_start = Clock::now();
  const raygate::Image image = raygate::render::render(
      world, camera, {options.accel, options.sampling, options.max_depth}, report.stats);
  report.render_seconds = seconds_since(render_start);
  report.cpu_seconds = process_cpu_seconds() - cpu_start;

  std::string error;
  if (!raygate::write_image(options.output_path, image, error) ||
      (!options.stats_path.empty() && !write_stats(options.stats_path, report, error))) {
    fmt::print(stderr, "raygate-baseline: {}\n", error);
    return kExitOutputFailed;
  }
  if (options.print_time) {
    fmt::print("raygate-baseline: in-process seconds {:.6f}\n",
               report.parse_seconds + report.prepare_seconds + report.render_seconds);
  }
  return kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  CLI::App app{"raygate-baseline: the reference Whitted ray tracer for NFF scenes"};
  add_options(app, options);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }
  try {
    return run(options);
  } catch (const raygate::nff::ParseError& e) {
    fmt::print(stderr, "{}\n", e.what());
    return kExitUsage;
  } catch (const raygate::render::SceneError& e) {
    const std::string label = options.scene_path == "-" ? "<stdin>" : options.scene_path;
    fmt::print(stderr, "{}: {}\n", label, e.what());
    return kExitUsage;
  } catch (const std::bad_alloc&) {
    fmt::print(stderr, "raygate-baseline: out of memory\n");
    return kExitOutputFailed;
  }
}

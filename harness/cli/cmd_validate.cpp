// `raygate validate`: proof that the baseline traces the SPD scenes the way the SPD intends.
// It renders the seven classic scenes with the SPD test procedure (512x512, corner rays, depth 5)
// and compares the baseline's ray counts with the published SPD statistics (spd-spec.md
// Table E), which a correct classical ray tracer should match within about 10%.
#include <fmt/core.h>

#include <array>
#include <cmath>
#include <memory>

#include "cli/commands.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/paths.h"
#include "runner/baseline_tool.h"
#include "runner/scene_files.h"

namespace raygate::cli {
namespace {

// Published figures (SPD Readme via spd-spec.md Table E; the teapot's are for size 12).
struct PublishedCounts {
  const char* scene;
  int size;  // 0: the SPD default
  long eye_hits;
  long reflection;
  long refraction;
  long shadow;
};

constexpr std::array<PublishedCounts, 7> kPublished{{
    {"balls", 0, 263169, 175095, 0, 954368},
    {"gears", 0, 245086, 304643, 207564, 2246955},
    {"mount", 0, 173125, 354769, 354769, 412922},
    {"rings", 0, 263169, 315236, 0, 1085002},
    {"teapot", 12, 161120, 225248, 0, 407656},
    {"tetra", 0, 49788, 0, 0, 46112},
    {"tree", 0, 169836, 0, 0, 1097419},
}};

constexpr double kTolerance = 0.10;

struct ValidateArgs {
  std::string accel = "bbox";
  std::vector<std::string> scenes;
  std::string work_dir = ".raygate/validate";
  std::string markdown;
  std::string baseline;
};

// Relative deviation; a published zero must be matched exactly.
double deviation(long ours, long published) {
  if (published == 0) return ours == 0 ? 0.0 : INFINITY;
  return static_cast<double>(ours - published) / static_cast<double>(published);
}

std::string cell(long ours, long published, bool& ok) {
  const double d = deviation(ours, published);
  const bool within = std::abs(d) <= kTolerance;
  ok = ok && within;
  if (published == 0) return fmt::format("{} / {}{}", ours, published, within ? "" : " **off**");
  return fmt::format("{} / {} ({:+.1f}%){}", ours, published, 100.0 * d, within ? "" : " **off**");
}

bool selected(const ValidateArgs& args, const std::string& scene) {
  if (args.scenes.empty()) return true;
  for (const std::string& s : args.scenes) {
    if (s == scene) return true;
  }
  return false;
}

int run_validate(const ValidateArgs& args) {
  for (const std::string& s : args.scenes) {
    bool known = false;
    for (const PublishedCounts& p : kPublished) known = known || s == p.scene;
    if (!known) throw UsageError("validate: no published statistics for scene '" + s + "'");
  }
  if (args.accel != "bbox" && args.accel != "none") {
    throw UsageError("--accel: expected none or bbox, found '" + args.accel + "'");
  }
  const BaselineTool baseline(locate_tools(args.baseline).baseline);
  const std::filesystem::path work = args.work_dir;
  std::string table =
      "| scene | eye rays that hit | reflection rays | refraction rays | shadow rays | "
      "render s |\n|---|---|---|---|---|---|\n";
  bool all_ok = true;
  for (const PublishedCounts& p : kPublished) {
    if (!selected(args, p.scene)) continue;
    const SuiteScene scene{p.size == 0 ? p.scene : fmt::format("{}-s{}", p.scene, p.size), p.scene,
                           p.size, 512, 512};
    const std::filesystem::path nff = prepare_scene(scene, work / "scenes");
    BaselineOptions options;
    options.accel = args.accel;
    options.sampling = "corners";
    fmt::print(stderr, "validate: rendering {} (512x512 corners, accel {})...\n", scene.id,
               args.accel);
    const BaselineRender r = baseline.render(nff, work / (scene.id + ".png"), options);
    if (!r.process.succeeded()) {
      throw InfraError("raygate-baseline " + r.process.describe() + " on " + nff.string() +
                       "\n" + log_tail(r.log, 10));
    }
    const auto& rays = r.stats.at("rays");
    bool ok = true;
    table += fmt::format("| {} | {} | {} | {} | {} | {:.1f} |\n", scene.id,
                         cell(rays.at("eye_hits").get<long>(), p.eye_hits, ok),
                         cell(rays.at("reflection").get<long>(), p.reflection, ok),
                         cell(rays.at("refraction").get<long>(), p.refraction, ok),
                         cell(rays.at("shadow").get<long>(), p.shadow, ok),
                         r.stats.at("render_seconds").get<double>());
    all_ok = all_ok && ok;
  }
  table += fmt::format("\nEach cell: baseline / published (deviation). Tolerance ±{:.0f}%. {}\n",
                       100 * kTolerance, baseline.version_line());
  fmt::print("{}", table);
  if (!args.markdown.empty()) write_file_atomically(args.markdown, table);
  return all_ok ? 0 : to_int(ExitCode::regression);
}

}  // namespace

void add_validate_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ValidateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "validate", "Compare the baseline's SPD ray counts with the published SPD statistics");
  cmd->add_option("scenes", args->scenes, "Classic scenes to check (default: all seven)");
  cmd->add_option("--accel", args->accel, "none or bbox (same counts; bbox is faster)")
      ->capture_default_str();
  cmd->add_option("--work-dir", args->work_dir, "Where scenes and renders go")
      ->capture_default_str();
  cmd->add_option("--markdown", args->markdown, "Also write the table to this file");
  cmd->add_option("--baseline", args->baseline, "raygate-baseline to use (default: beside raygate)");
  cmd->callback([args, &exit_code] { exit_code = run_validate(*args); });
}

}  // namespace raygate::cli

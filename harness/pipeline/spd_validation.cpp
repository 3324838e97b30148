#include "pipeline/spd_validation.h"

#include <fmt/core.h>

#include <array>
#include <cmath>

#include "core/error.h"
#include "core/fs.h"
#include "core/json_reader.h"
#include "core/paths.h"
#include "runner/baseline_tool.h"
#include "runner/scene_files.h"

namespace raygate {
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

bool selected(const SpdValidationRequest& args, const std::string& scene) {
  if (args.scenes.empty()) return true;
  for (const std::string& s : args.scenes) {
    if (s == scene) return true;
  }
  return false;
}

// One table row: the baseline's ray counts against the published ones. Statistics without
// the counts (a baseline that is not raygate's) are named, not a library's exception text.
std::string counts_row(const std::string& id, const BaselineRender& r, const PublishedCounts& p,
                       bool& all_ok) {
  try {
    const auto& rays = r.stats.at("rays");
    bool ok = true;
    std::string row = fmt::format("| {} | {} | {} | {} | {} | {:.1f} |\n", id,
                                  cell(rays.at("eye_hits").get<long>(), p.eye_hits, ok),
                                  cell(rays.at("reflection").get<long>(), p.reflection, ok),
                                  cell(rays.at("refraction").get<long>(), p.refraction, ok),
                                  cell(rays.at("shadow").get<long>(), p.shadow, ok),
                                  r.stats.at("render_seconds").get<double>());
    all_ok = all_ok && ok;
    return row;
  } catch (const nlohmann::json::exception& e) {
    throw InfraError(r.stats_path.string() +
                     ": raygate-baseline's statistics lack the ray counts (" +
                     plain_exception_text(e) + ")");
  }
}

}  // namespace

SpdValidation validate_spd_counts(const SpdValidationRequest& args,
                                  const std::function<void(const std::string&)>& status) {
  for (const std::string& s : args.scenes) {
    bool known = false;
    for (const PublishedCounts& p : kPublished) known = known || s == p.scene;
    if (!known) throw UsageError("validate: no published statistics for scene '" + s + "'");
  }
  if (args.accel != "bbox" && args.accel != "none") {
    throw UsageError("--accel: expected none or bbox, found '" + args.accel + "'");
  }
  const BaselineTool baseline(locate_tools(args.baseline).baseline);
  const std::filesystem::path work = std::filesystem::absolute(args.work_dir);  // "-" is no option
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
    status(
        fmt::format("validate: rendering {} (512x512 corners, accel {})...", scene.id, args.accel));
    const BaselineRender r = baseline.render(nff, work / (scene.id + ".png"), options);
    if (!r.process.succeeded()) {
      throw InfraError("raygate-baseline " + r.process.describe() + " on " + nff.string() + "\n" +
                       log_tail(r.log, 10));
    }
    table += counts_row(scene.id, r, p, all_ok);
  }
  table += fmt::format("\nEach cell: baseline / published (deviation). Tolerance ±{:.0f}%. {}\n",
                       100 * kTolerance, baseline.version_line());
  return {table, all_ok};
}

}  // namespace raygate

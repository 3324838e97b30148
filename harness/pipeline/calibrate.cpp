#include "pipeline/calibrate.h"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/format.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/path_component.h"
#include "pipeline/output_failures.h"
#include "core/time_text.h"
#include "pipeline/revision_setup.h"
#include "pipeline/suite_measurement.h"
#include "runner/tracer_contender.h"

namespace raygate {

namespace {

// The view's resolution as the generated NFF file says it (a scene at its own resolution).
std::pair<int, int> nff_resolution(const std::filesystem::path& nff) {
  std::istringstream text(read_file(nff));
  std::string line;
  while (std::getline(text, line)) {
    std::istringstream words(line);
    std::string keyword;
    int width = 0;
    int height = 0;
    if (words >> keyword && keyword == "resolution" && words >> width >> height && width > 0 &&
        height > 0) {
      return {width, height};
    }
  }
  throw InfraError(nff.string() + ": no resolution line in the generated scene");
}

// What measuring one scene at one resolution needs: where its files go, and how it is run.
struct RenderTimer {
  const CalibrateRequest& request;
  const TracerContender& tracer;
  std::filesystem::path work_dir;
  PipelineIo& io;

  TimedRender time(SuiteScene entry, int width, int height) const {
    entry.width = width;
    entry.height = height;
    const std::string label = fmt::format("{}x{}", width, height);
    SuiteMeasurement m;
    m.scene_cache = request.context.cache_dir / "scenes" / "calibrate" / label;
    m.formats = {request.context.adapter.scene_format};
    const SceneInput input = prepare_scene_input(entry, m);
    ScheduleOptions schedule = request.context.schedule;
    schedule.kind = ScheduleKind::alternate;  // one program: nothing to pair
    schedule.warmup_runs = 0;  // the smaller render warms the larger's program and files
    schedule.normalizer_rounds = 0;
    schedule.repeats = 1;
    schedule.repeats_from_rounds = {};
    const std::size_t runs = request.runs;
    const StopRule enough = [runs](const std::vector<Round>& rounds, double) {
      return rounds.size() >= runs ? StopDecision::stop_converged
                                   : StopDecision::continue_measuring;
    };
    const Contender* contenders[] = {&tracer};
    const SceneRuns measured =
        measure_scene(input, contenders, schedule, enough, io.executor, io.clock,
                      join_component(work_dir, entry.id, "scene id") / label);
    if (measured.failed()) {
      throw InfraError(fmt::format("{} at {}: the tracer failed: {} (log: {})", entry.id, label,
                                   measured.failed_run->failure,
                                   measured.failed_run->log.string()));
    }
    TimedRender fastest{width, height, std::numeric_limits<double>::infinity(), 0.0};
    for (const Round& round : measured.rounds) {
      const RunRecord& run = round.runs.at(tracer.name());
      if (run.wall_seconds < fastest.seconds) {
        fastest.seconds = run.wall_seconds;
        fastest.timed_seconds = run.seconds;
      }
    }
    return fastest;
  }
};

SceneCalibration calibrate_scene(const SuiteScene& entry, const RenderTimer& timer,
                                 const CalibrateRequest& request) {
  int width = entry.width;
  int height = entry.height;
  if (width == 0) {  // the scene's own resolution: generate it to read it
    SuiteMeasurement m;
    m.scene_cache = request.context.cache_dir / "scenes" / "calibrate" / "own";
    std::tie(width, height) = nff_resolution(prepare_scene_input(entry, m).nff);
  }
  SceneCalibration scene;
  scene.entry = entry;
  if (width < 2 && height < 2) {
    throw UsageError(fmt::format("{}: {}x{} is too small to calibrate (two sizes are timed)",
                                 entry.id, width, height));
  }
  scene.smaller = timer.time(entry, std::max(1, width / 2), std::max(1, height / 2));
  scene.larger = timer.time(entry, width, height);
  scene.model = fit_render_time(scene.smaller, scene.larger);
  // Never larger than the suite's own: the baseline renders the same pictures, and the suite
  // is sized for it (about 1 s at ci's), so a larger picture for a fast tracer with a slow
  // start-up would make the baseline's runs the measurement's cost.
  scene.chosen = choose_resolution(scene.model, width, height, request.target_seconds,
                                   std::min(request.min_side, std::min(width, height)),
                                   std::max(width, height));
  return scene;
}

std::string default_suite_name(const CalibrateRequest& request) {
  return request.context.suite.name + "-" + request.context.adapter.name;
}

}  // namespace

void check_calibrate_request(const CalibrateRequest& request) {
  if (!(request.target_seconds > 0.0) || !std::isfinite(request.target_seconds) ||
      request.target_seconds > 3600.0) {
    throw UsageError(
        fmt::format("--target-seconds {}: expected seconds in (0, 3600]", request.target_seconds));
  }
  if (request.runs < 1 || request.runs > 20) {
    throw UsageError(fmt::format("--runs {}: expected 1..20", request.runs));
  }
  if (request.min_side < 1 || request.min_side > 4096) {
    throw UsageError(fmt::format("--min-side {}: expected 1..4096", request.min_side));
  }
  if (request.out.empty()) throw UsageError("-o: the suite file to write is required");
  // A folder, a device, or a folder raygate cannot write into: said now, not after the renders.
  check_output_path(request.out, "-o");
  // Calibrating a suite into its own file would replace the sizes it was measured from; into
  // the adapter's, the adapter.
  check_distinct_files({{"--suite", request.context.suite.path},
                        {"--adapter", request.context.adapter.file},
                        {"-o", request.out}});
  if (request.out.extension() != ".json") {
    throw UsageError("-o " + request.out.string() +
                     ": a suite file ends in .json (so --suite reads it as a file)");
  }
  const std::string name =
      request.suite_name.empty() ? default_suite_name(request) : request.suite_name;
  checked_component(name, "--name");  // it names the suite's scene cache folder
}

std::string calibration_summary(const Calibration& calibration, double target_seconds) {
  std::size_t reached = 0;
  for (const SceneCalibration& scene : calibration.scenes) reached += scene.chosen.reached;
  return fmt::format(
      "wrote suite '{}' to {}: {} of {} predicted within 10% of {:g} s; use it with --suite {}",
      calibration.suite.name, calibration.path.string(), reached,
      count_text(calibration.scenes.size(), "scene"), target_seconds, calibration.path.string());
}

std::string calibration_line(const SceneCalibration& s, double target_seconds) {
  std::string line = fmt::format(
      "{:<10} {}x{} {:.3f} s, {}x{} {:.3f} s -> {}x{}, predicted {:.3f} s (fixed {:.3f} s)",
      s.entry.id, s.larger.width, s.larger.height, s.larger.seconds, s.smaller.width,
      s.smaller.height, s.smaller.seconds, s.chosen.width, s.chosen.height,
      s.chosen.predicted_seconds, s.model.fixed_seconds);
  // A tracer timed by CPU seconds that waits (start-up, I/O): the budget pays wall seconds,
  // the ratio sees fewer.
  if (std::abs(s.larger.timed_seconds - s.larger.seconds) > 0.1 * s.larger.seconds) {
    line += fmt::format("  [{}x{}: {:.3f} s by the adapter's clock]", s.larger.width,
                        s.larger.height, s.larger.timed_seconds);
  }
  if (!s.chosen.reached && s.model.fixed_seconds >= target_seconds) {
    line += fmt::format(
        "  NOT REACHED: the fixed part alone is over {:g} s (a smaller --size, "
        "or a longer target)",
        target_seconds);
  } else if (!s.chosen.reached && s.chosen.predicted_seconds < target_seconds) {
    line += fmt::format(
        "  NOT REACHED: under {:g} s at the suite's own resolution, the largest "
        "calibrate chooses (the baseline renders it too)",
        target_seconds);
  } else if (!s.chosen.reached) {
    line += fmt::format("  NOT REACHED: a side limit stops it short of {:g} s", target_seconds);
  } else if (s.model.fixed_seconds > 0.5 * s.chosen.predicted_seconds) {
    // Most of the render is start-up and set-up: its ratio says little about rendering.
    line += fmt::format("  (the fixed part is {:.0f}% of it)",
                        100.0 * s.model.fixed_seconds / s.chosen.predicted_seconds);
  }
  return line;
}

std::string calibrated_suite_text(const Suite& source, const std::string& name,
                                  const std::string& description,
                                  const std::vector<SceneCalibration>& scenes) {
  using nlohmann::json;
  std::string text = "{\n";
  text += "  \"name\": " + json(name).dump() + ",\n";
  text += "  \"description\": " + json(description).dump() + ",\n";
  text += "  \"sampling\": " + json(source.sampling).dump() + ",\n";
  text += "  \"scenes\": [\n";
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const SuiteScene& e = scenes[i].entry;
    text +=
        fmt::format("    {{\"id\": {}, \"scene\": {}, ", json(e.id).dump(), json(e.scene).dump());
    if (e.size > 0) text += fmt::format("\"size\": {}, ", e.size);
    text += fmt::format("\"resolution\": [{}, {}]}}{}\n", scenes[i].chosen.width,
                        scenes[i].chosen.height, i + 1 < scenes.size() ? "," : "");
  }
  text += "  ]\n}\n";
  return text;
}

Calibration calibrate_suite(const CalibrateRequest& request, PipelineIo& io) {
  check_calibrate_request(request);
  const MeasureContext& context = request.context;
  const PreparedRevision tracer =
      prepare_revision(Role::tracer, request.repository, request.worktree, context,
                       request.baseline.source_hash(), context.jobs, io.progress);
  const TracerContender contender(tracer.setup);
  const RenderTimer timer{
      request, contender,
      fresh_run_dir(context.cache_dir / "runs",
                    compact_utc_timestamp() + "-calibrate-" + request.worktree.short_sha),
      io};
  io.progress.line(fmt::format(
      "calibrating {} {} on suite {}: {}, each timed at its resolution and at half each "
      "side (wall seconds, the fastest of {}), for {:g} s a render",
      context.adapter.name, request.worktree.short_sha, context.suite.name,
      count_text(context.scenes.size(), "scene"), request.runs, request.target_seconds));
  Calibration calibration;
  for (const SuiteScene& entry : context.scenes) {
    calibration.scenes.push_back(calibrate_scene(entry, timer, request));
    io.progress.line(calibration_line(calibration.scenes.back(), request.target_seconds));
  }
  const std::string name =
      request.suite_name.empty() ? default_suite_name(request) : request.suite_name;
  const std::string description = fmt::format(
      "suite {} sized by raygate calibrate for adapter {} at {} ({}) on {}: each render about "
      "{:g} s of wall time on that machine",
      context.suite.name, context.adapter.name, request.worktree.short_sha, request.repository,
      utc_timestamp(), request.target_seconds);
  write_file_atomically(
      request.out, calibrated_suite_text(context.suite, name, description, calibration.scenes));
  calibration.path = request.out;
  calibration.suite = load_suite(request.out.string(), context.tools.data_root);
  return calibration;
}

}  // namespace raygate

#include "runner/baseline_contender.h"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "core/error.h"
#include "core/json_reader.h"
#include "core/fs.h"
#include "core/sha256.h"
#include "runner/timing/timing_modes.h"

namespace raygate {

namespace {

// PPM: no compression, so writing the image costs next to nothing; the harness reads it
// through OpenImageIO like any tracer's image.
constexpr const char* kImageName = "image.ppm";
constexpr const char* kStatsName = "stats.json";

// Parse + prepare + render seconds from the --stats file; throws if absent or not positive.
double in_process_seconds(const std::filesystem::path& stats_path) {
  const nlohmann::json stats = nlohmann::json::parse(read_file(stats_path));
  const double seconds = stats.at("parse_seconds").get<double>() +
                         stats.at("prepare_seconds").get<double>() +
                         stats.at("render_seconds").get<double>();
  if (!(seconds > 0.0) || !std::isfinite(seconds)) throw std::runtime_error("no positive time");
  return seconds;
}

}  // namespace

BaselineContender::BaselineContender(std::filesystem::path executable, std::string sampling,
                                     std::chrono::milliseconds timeout, std::string accel,
                                     const TimingMode* clock)
    : Contender(Role::baseline),
      executable_(std::move(executable)),
      sampling_(std::move(sampling)),
      timeout_(timeout),
      accel_(std::move(accel)),
      clock_(clock != nullptr ? clock : &timing_mode("wall")) {}

ProcessSpec BaselineContender::command(const SceneInput& scene,
                                       const std::filesystem::path& run_dir) const {
  ProcessSpec spec;
  spec.argv = {executable_.string(),
               scene.nff.string(),
               "-o",
               (run_dir / kImageName).string(),
               "--accel",
               accel_,
               "--sampling",
               sampling_};
  spec.working_directory = run_dir;
  spec.stdout_path = run_dir / "log.txt";
  spec.stderr_path = spec.stdout_path;
  spec.timeout = timeout_;
  // Not for an exact mode: formatting --stats' measured seconds costs a different number of
  // instructions each run (41 in 1.1e9 on tetra, measured), and would make the count
  // unrepeatable.
  if (!clock_->exact()) {
    spec.argv.insert(spec.argv.end(), {"--stats", (run_dir / kStatsName).string()});
  }
  if (clock_->under_cachegrind() && !simulation_) {
    throw std::logic_error("BaselineContender: a mode under cachegrind without simulate()");
  }
  // The mode starts the process, as it does the tracer's (the process itself for a clock).
  const std::optional<Cachegrind> simulator =
      simulation_ ? std::optional(simulation_->cachegrind) : std::nullopt;
  return clock_->wrap(std::move(spec), run_dir, simulator);
}

BaselineCostKey BaselineContender::cost_key(const SceneInput& scene) const {
  return {simulation_->source_sha256, simulation_->cachegrind.version, sha256_file_hex(scene.nff),
          sampling_, accel_};
}

std::optional<RunRecord> BaselineContender::known_run(const SceneInput& scene) const {
  if (!clock_->under_cachegrind() || !simulation_ || !simulation_->cache) return std::nullopt;
  const std::optional<SimulatedCounters> counters = simulation_->cache->find(cost_key(scene));
  if (!counters) return std::nullopt;
  RunRecord run;
  run.ok = true;
  run.outcome = "not run: simulated cost cached in " + simulation_->cache->dir().string();
  run.simulated = counters;
  run.seconds = estimated_cycles(*counters);
  return run;
}

RunRecord BaselineContender::interpret(const SceneInput& scene, const ProcessResult& result,
                                       const ProcessSpec& spec,
                                       const std::filesystem::path& run_dir) const {
  RunRecord run = record_process(result, spec);
  run.image = run_dir / kImageName;
  const double own_limit_seconds = std::chrono::duration<double>(kBaselineRunLimit).count();
  if (result.outcome == ProcessOutcome::timed_out &&
      result.wall_seconds < own_limit_seconds - 0.5) {
    run.stopped_by_budget = true;  // as a tracer's (tracer_contender.cpp): the budget's, said so
    run.failure +=
        " (the time budget's cut, not raygate-baseline's 30-minute limit: give "
        "--max-seconds or --max-minutes more)";
  }
  if (!run.ok) return run;
  if (!clock_->exact()) {  // its own account of its time, as a tracer's regex gives one
    try {
      run.reported_seconds = in_process_seconds(run_dir / kStatsName);
    } catch (const std::exception& e) {
      run.ok = false;
      run.failure = "raygate-baseline wrote unusable statistics " +
                    (run_dir / kStatsName).string() + ": " + plain_exception_text(e);
      return run;
    }
  }
  clock_->collect(run, run_dir);  // what the mode reads or derives, as for the tracer
  if (!run.ok) return run;
  if (run.simulated && simulation_ && simulation_->cache) {
    simulation_->cache->observe(cost_key(scene), *run.simulated);
  }
  run.seconds = clock_->seconds(run).value_or(0.0);
  if (!(run.seconds > 0.0)) {  // the denominator of every ratio
    run.ok = false;
    run.failure = fmt::format("raygate-baseline took no measurable {} time (in {})",
                              clock_->baseline_clock(), clock_->unit());
  }
  return run;
}

}  // namespace raygate

#include "runner/baseline_contender.h"

#include <cmath>

#include "core/fs.h"

namespace raygate {

BaselineContender::BaselineContender(std::filesystem::path executable, std::string sampling,
                                     std::chrono::milliseconds timeout, std::string accel,
                                     TimingMetric metric)
    : Contender("baseline"),
      executable_(std::move(executable)),
      sampling_(std::move(sampling)),
      timeout_(timeout),
      accel_(std::move(accel)),
      metric_(metric) {}

ProcessSpec BaselineContender::command(const SceneInput& scene,
                                       const std::filesystem::path& run_dir) const {
  ProcessSpec spec;
  spec.argv = {executable_.string(),       scene.nff.string(), "-o",
               (run_dir / "image.png").string(), "--accel", accel_,
               "--sampling",               sampling_,          "--stats",
               (run_dir / "stats.json").string()};
  spec.working_directory = run_dir;
  spec.stdout_path = run_dir / "log.txt";
  spec.stderr_path = spec.stdout_path;
  spec.timeout = timeout_;
  return spec;
}

RunRecord BaselineContender::interpret(const SceneInput& /*scene*/, const ProcessResult& result,
                                       const ProcessSpec& spec,
                                       const std::filesystem::path& run_dir) const {
  RunRecord run = record_process(result, spec);
  run.image = run_dir / "image.png";
  if (!run.ok) return run;
  try {
    const nlohmann::json stats = nlohmann::json::parse(read_file(run_dir / "stats.json"));
    const double seconds = metric_ == TimingMetric::cpu
                               ? stats.at("cpu_seconds").get<double>()
                               : stats.at("parse_seconds").get<double>() +
                                     stats.at("prepare_seconds").get<double>() +
                                     stats.at("render_seconds").get<double>();
    if (!(seconds > 0.0) || !std::isfinite(seconds)) throw std::runtime_error("no positive time");
    run.reported_seconds = seconds;
    run.seconds = seconds;
  } catch (const std::exception& e) {
    run.ok = false;
    run.failure = "raygate-baseline wrote unusable statistics " + (run_dir / "stats.json").string() +
                  ": " + e.what();
  }
  return run;
}

}  // namespace raygate

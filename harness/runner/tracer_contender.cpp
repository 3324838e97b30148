#include "runner/tracer_contender.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdint>
#include <system_error>
#include <thread>

#include "core/error.h"
#include "adapter/timing_regex.h"
#include "core/fs.h"
#include "nff/parser.h"
#include "runner/timing/timing_modes.h"

namespace raygate {

namespace {

// The image size the scene asks for: the suite entry's resolution, or else the one its NFF view
// was generated with (the SPD default), read from the file only in that case.
std::pair<int, int> image_size(const SceneInput& scene) {
  if (scene.entry.width > 0 && scene.entry.height > 0) {
    return {scene.entry.width, scene.entry.height};
  }
  try {
    const nff::Scene parsed = nff::read_nff_file(scene.nff.string());
    return {parsed.view.width, parsed.view.height};
  } catch (const nff::ParseError& e) {
    throw UsageError(e.what());
  }
}

// {seed}: FNV-1a of the run's own directory (<run>/scenes/<id>/<role>/<label>), 31 bits. Every
// run gets its own seed, within a measurement and across measurements (each has a fresh run
// directory), so repeated compares are independent samples, as a statistical check needs.
std::string run_seed(const std::filesystem::path& run_dir) {
  std::uint32_t hash = 2166136261u;
  for (const char c : run_dir.lexically_normal().string()) {
    hash = (hash ^ static_cast<unsigned char>(c)) * 16777619u;
  }
  return std::to_string(hash & 0x7FFFFFFFu);
}

}  // namespace

TracerContender::TracerContender(TracerSetup setup)
    : Contender(setup.role), setup_(std::move(setup)) {}

const TimingMode& TracerContender::timing() const {
  return setup_.timing != nullptr ? *setup_.timing : adapter_timing_mode(setup_.adapter.timing);
}

Placeholders TracerContender::placeholders(const SceneInput& scene,
                                           const std::filesystem::path& run_dir) const {
  const std::filesystem::path& scene_file = scene.file(setup_.adapter.scene_format);
  const std::filesystem::path workdir = run_dir / "work";
  Placeholders values;
  values.src = setup_.build.src_dir.string();
  values.repo_root = setup_.repo_root.string();
  values.build = setup_.build.build_dir.string();
  values.threads = std::to_string(setup_.adapter.threads);
  values.scene = scene_file.string();
  values.image = (workdir / "image.png").string();
  values.workdir = workdir.string();
  values.raygate_source = setup_.raygate_source.string();
  values.scene_stem = scene_file.stem().string();
  const auto [width, height] = image_size(scene);
  values.width = std::to_string(width);
  values.height = std::to_string(height);
  values.seed = run_seed(run_dir);
  return values;
}

ProcessSpec TracerContender::command(const SceneInput& scene,
                                     const std::filesystem::path& run_dir) const {
  const Adapter& adapter = setup_.adapter;
  const Placeholders values = placeholders(scene, run_dir);
  std::filesystem::create_directories(*values.workdir);
  ProcessSpec spec;
  spec.argv = expand(adapter.run, values);
  spec.working_directory = expand(adapter.cwd, values);
  for (const auto& [name, value] : adapter.env) spec.environment[name] = expand(value, values);
  if (adapter.stdin_template) spec.stdin_path = expand(*adapter.stdin_template, values);
  spec.stdout_path = run_dir / "log.txt";
  spec.stderr_path = spec.stdout_path;
  const double timeout_seconds =
      setup_.run_timeout_seconds > 0.0 ? setup_.run_timeout_seconds : adapter.timeouts.run_seconds;
  spec.timeout = std::chrono::milliseconds(static_cast<long long>(timeout_seconds * 1000));
  spec.cpu_affinity = setup_.cpus;
  return timing().wrap(std::move(spec), run_dir, setup_.cachegrind);
}

namespace {

std::string image_problem(const std::filesystem::path& image,
                          const std::filesystem::path& run_dir) {
  std::error_code error;
  if (std::filesystem::is_symlink(std::filesystem::symlink_status(image, error))) {
    // A link out of the run's fresh folder could name an earlier run's image (or anything).
    const auto target = std::filesystem::weakly_canonical(image, error);
    const auto folder = std::filesystem::weakly_canonical(run_dir, error);
    const auto inside = target.lexically_relative(folder);
    if (inside.empty() || *inside.begin() == "..") {
      return fmt::format(
          "left its image as a symbolic link to {}, outside its run folder {}: "
          "an image must be a file the run wrote",
          target.string(), run_dir.string());
    }
  }
  const auto status = std::filesystem::status(image, error);
  if (error || !std::filesystem::exists(status)) return "wrote no image at " + image.string();
  if (!std::filesystem::is_regular_file(status)) return image.string() + " is not a regular file";
  if (std::filesystem::file_size(image, error) == 0 || error) {
    return "wrote an empty image at " + image.string();
  }
  return {};
}

// A reported time the process could not have spent (the sweep's `RTIME: 1e308` from a 0.03 s
// process, or a unit of ms read as s): its threads' time at most, with the clocks' slack. Taken,
// it was written into documents raygate's own readers refuse.
std::string reported_time_problem(double reported_seconds, const ProcessResult& result,
                                  const Adapter& adapter) {
  // A microsecond is below any render's time (and a clock's print resolution): a smaller time is
  // a number the regex took from elsewhere, and would make the tracer's score zero.
  constexpr double kShortestRenderSeconds = 1e-6;
  if (reported_seconds < kShortestRenderSeconds) {
    return fmt::format(
        "printed a time of {:.6g} s, less than a microsecond: timing.regex or timing.unit does "
        "not read what the tracer prints",
        reported_seconds);
  }
  // Threads beyond the machine's CPUs do not run at once, so they add no CPU time per second.
  const unsigned cpus = std::max(std::thread::hardware_concurrency(), 1U);
  const double threads =
      static_cast<double>(std::clamp(adapter.threads, 1, static_cast<int>(cpus)));
  if (reported_seconds <= result.wall_seconds * threads * 1.05 + 0.05) return "";
  return fmt::format(
      "printed a time of {:.6g} s, longer than its process ran ({:.3f} s of wall time{}): "
      "timing.regex or timing.unit does not read what the tracer prints",
      reported_seconds, result.wall_seconds,
      adapter.threads > 1 ? fmt::format(", {} threads", adapter.threads) : "");
}

}  // namespace

RunRecord TracerContender::interpret(const SceneInput& scene, const ProcessResult& result,
                                     const ProcessSpec& spec,
                                     const std::filesystem::path& run_dir) const {
  const Adapter& adapter = setup_.adapter;
  RunRecord run = record_process(result, spec);
  if (result.outcome == ProcessOutcome::timed_out &&
      result.wall_seconds < adapter.timeouts.run_seconds - 0.5) {
    run.stopped_by_budget = true;
    run.failure += fmt::format(
        " (the time budget's cut, not the adapter's {:g} s timeout_s.run: give --max-seconds "
        "or --max-minutes more)",
        adapter.timeouts.run_seconds);
  }
  run.image = expand(adapter.image, placeholders(scene, run_dir));
  if (!run.ok) return run;
  if (const std::string problem = image_problem(run.image, run_dir); !problem.empty()) {
    run.ok = false;
    run.failure = adapter.name + " " + problem;
    return run;
  }
  // The adapter's regex is read whenever it has one: the tracer's own account of its time.
  if (adapter.timing.source == TimingSource::reported) {
    std::optional<double> reported;
    try {
      reported = parse_reported_seconds(adapter, read_file(spec.stdout_path));
    } catch (const RegexTooCostly& e) {
      run.ok = false;
      run.failure = adapter.name + ": " + e.what();
      return run;
    }
    if (!reported || *reported <= 0.0) {
      run.ok = false;
      run.failure = adapter.name + " printed no positive time matching timing.regex '" +
                    adapter.timing.regex + "'";
      return run;
    }
    if (const std::string problem = reported_time_problem(*reported, result, adapter);
        !problem.empty()) {
      run.ok = false;
      run.failure = adapter.name + " " + problem;
      return run;
    }
    run.reported_seconds = reported;
  }
  timing().collect(run, run_dir);
  if (!run.ok) return run;
  run.seconds = timing().seconds(run).value_or(0.0);
  return run;
}

}  // namespace raygate

#include "doctor/noise.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <vector>

#include "core/enum_words.h"
#include "core/error.h"
#include "core/json_reader.h"
#include "core/fs.h"
#include "core/process.h"
#include "doctor/system_facts.h"
#include "measure/descriptive.h"
#include "runner/baseline_contender.h"
#include "runner/scene_files.h"
#include "runner/timing/timing_modes.h"

namespace raygate {
namespace {

TimeSpread spread_of(const std::vector<double>& values) {
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  return {median(values), coefficient_of_variation(values), *high / *low};
}

// Why the doctor's run of the baseline failed, with the end of its log: the log is in the
// doctor's temporary folder, which is gone by the time the message is read.
InfraError baseline_failure(const std::string& why, const ProcessSpec& spec) {
  const std::string tail = log_tail(spec.stdout_path, 10);
  return InfraError(
      fmt::format("raygate-baseline could not run the doctor's scene: {}{}", why,
                  tail.empty() ? " (its log is empty)" : "; its log ended:\n" + tail));
}

// One timed run of the baseline: the contender's own command and interpretation (its in-process
// seconds), plus the in-process CPU seconds from its --stats file.
NoiseRun run_once(const BaselineContender& baseline, const SceneInput& scene,
                  const std::filesystem::path& run_dir) {
  std::filesystem::create_directories(run_dir);
  const ProcessSpec spec = baseline.command(scene, run_dir);
  const RunRecord run = baseline.interpret(scene, run_process(spec), spec, run_dir);
  if (!run.ok) {
    throw baseline_failure(run.outcome + (run.failure.empty() ? "" : "; " + run.failure), spec);
  }
  double cpu_seconds = 0.0;
  try {
    cpu_seconds =
        nlohmann::json::parse(read_file(run_dir / "stats.json")).at("cpu_seconds").get<double>();
  } catch (const std::exception& e) {
    throw baseline_failure(
        std::string("its --stats file has no cpu_seconds (") + plain_exception_text(e) + ")", spec);
  }
  return {run.seconds, cpu_seconds};
}

std::optional<double> steal_between(const std::optional<CpuTimes>& before,
                                    const std::optional<CpuTimes>& after) {
  if (!before || !after || after->total <= before->total || after->steal < before->steal) {
    return std::nullopt;
  }
  return static_cast<double>(after->steal - before->steal) /
         static_cast<double>(after->total - before->total);
}

// The grades' words, as the report prints them and its JSON writes them.
constexpr EnumWords<NoiseGrade, 3> kGradeWords{
    {{NoiseGrade::good, "good"}, {NoiseGrade::fair, "fair"}, {NoiseGrade::noisy, "noisy"}}};

}  // namespace

std::string to_string(NoiseGrade grade) { return std::string(word_of(kGradeWords, grade, "?")); }

NoiseGrade grade_noise(double ratio_cv) {
  if (ratio_cv < kNoiseGoodCv) return NoiseGrade::good;
  if (ratio_cv < kNoiseFairCv) return NoiseGrade::fair;
  return NoiseGrade::noisy;
}

std::string NoiseScore::advice() const {
  switch (grade) {
    case NoiseGrade::good:
      return fmt::format(
          "identical runs agree within {:.1f}% (CV): a 3% gate threshold stands "
          "well clear of this machine's noise",
          100.0 * ratio_cv);
    case NoiseGrade::fair:
      return fmt::format(
          "identical runs differ by {:.1f}% (CV): gates work but need more rounds "
          "(--max-rounds) to call a 3% change; fix the warnings above",
          100.0 * ratio_cv);
    case NoiseGrade::noisy:
      return fmt::format(
          "identical runs differ by {:.1f}% (CV): a gate at 3% will be "
          "inconclusive or flaky here; fix the warnings above or gate on a "
          "quieter runner",
          100.0 * ratio_cv);
  }
  return {};
}

double NoiseScore::waiting_fraction() const {
  if (!(seconds.median > 0.0)) return 0.0;
  return std::max(0.0, 1.0 - cpu_seconds.median / seconds.median);
}

NoiseScore summarize_noise(std::span<const NoiseRound> rounds) {
  if (rounds.size() < 2) throw std::invalid_argument("a noise score needs at least 2 rounds");
  std::vector<double> seconds, cpu_seconds, ratios, log_ratios;
  for (const NoiseRound& r : rounds) {
    for (const NoiseRun* run : {&r.a, &r.b}) {
      if (!(run->seconds > 0.0) || !(run->cpu_seconds > 0.0)) {
        throw std::invalid_argument("a noise run with a time that is not positive");
      }
      seconds.push_back(run->seconds);
      cpu_seconds.push_back(run->cpu_seconds);
    }
    ratios.push_back(r.a.seconds / r.b.seconds);
    log_ratios.push_back(std::log(ratios.back()));
  }
  NoiseScore score;
  score.rounds = rounds.size();
  score.seconds = spread_of(seconds);
  score.cpu_seconds = spread_of(cpu_seconds);
  score.aa_ratio = std::exp(median(log_ratios));
  score.ratio_cv = coefficient_of_variation(ratios);
  score.ratio_spread = spread_of(ratios).spread;
  score.grade = grade_noise(score.ratio_cv);
  return score;
}

SuiteScene noise_scene() { return {"doctor-balls", "balls", 3, 128, 128}; }

NoiseScore measure_noise(const NoiseOptions& options) {
  if (options.rounds < 2) {
    throw UsageError(
        fmt::format("--rounds {}: a noise score needs at least 2 rounds", options.rounds));
  }
  SceneInput scene;
  scene.entry = noise_scene();
  scene.nff = prepare_scene(scene.entry, options.work_dir / "scenes");
  scene.files[SceneFormat::nff] = scene.nff;
  // In-process seconds: how the machine's speed wanders, without the process start-up that a
  // process-timed ratio divides out on both sides.
  const BaselineContender baseline(options.baseline, "center", std::chrono::minutes(2), "none",
                                   &timing_mode("reported"));
  const std::filesystem::path runs = options.work_dir / "runs";
  // Measured as raygate measures: idle CPUs held polling where the machine allows it.
  const IdlePollHold idle_polling(options.idle_poll_device);
  run_once(baseline, scene, runs / "warm-up");  // page cache, CPU caches, frequency ramp
  const auto before = read_cpu_times(options.root);
  std::vector<NoiseRound> rounds;
  for (int i = 0; i < options.rounds; ++i) {
    NoiseRound round;
    // Alternating order, as the runner's schedule does, so a first-run effect hits a and b alike.
    NoiseRun& first = i % 2 == 0 ? round.a : round.b;
    NoiseRun& second = i % 2 == 0 ? round.b : round.a;
    first = run_once(baseline, scene, runs / fmt::format("{}-1", i));
    second = run_once(baseline, scene, runs / fmt::format("{}-2", i));
    rounds.push_back(round);
  }
  NoiseScore score = summarize_noise(rounds);
  score.scene = fmt::format("{} size {}, {}x{}", scene.entry.scene, scene.entry.size,
                            scene.entry.width, scene.entry.height);
  score.steal_fraction = steal_between(before, read_cpu_times(options.root));
  return score;
}

}  // namespace raygate

// The doctor's measured noise score: raygate-baseline run in A/A pairs on a small fixed scene.
// The spread of its in-process seconds says how much this machine's speed wanders; the spread
// of the paired ratio A/B of two back-to-back identical runs says how much of that a gate still
// sees after normalization (an A/A normalized ratio: ideally exactly 1 every round).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "runner/idle_poll.h"
#include "runner/suite.h"

namespace raygate {

inline constexpr double kNoiseGoodCv = 0.01;  // below: a 3% gate threshold is 3x the noise
inline constexpr double kNoiseFairCv = 0.03;  // below: usable with more rounds
inline constexpr int kDefaultNoiseRounds = 10;

enum class NoiseGrade { good, fair, noisy };
std::string to_string(NoiseGrade grade);
NoiseGrade grade_noise(double ratio_cv);

struct NoiseRun {
  double seconds = 0.0;      // in-process parse + prepare + render
  double cpu_seconds = 0.0;  // in-process CPU seconds
};

struct NoiseRound {
  NoiseRun a;  // the two runs are identical; a runs first in even rounds, b in odd ones
  NoiseRun b;
};

struct TimeSpread {
  double median = 0.0;
  double cv = 0.0;      // sample standard deviation / mean
  double spread = 0.0;  // max / min
};

struct NoiseScore {
  std::string scene;  // "balls size 3, 128x128"
  std::size_t rounds = 0;
  TimeSpread seconds;         // over every run (2 per round)
  TimeSpread cpu_seconds;     // over every run
  double aa_ratio = 1.0;      // exp(median of ln(a / b)): the A/A normalized ratio
  double ratio_cv = 0.0;      // sample CV of a / b over rounds: the noise score
  double ratio_spread = 0.0;  // max / min of a / b
  NoiseGrade grade = NoiseGrade::good;
  std::optional<double> steal_fraction;  // of all CPU time while measuring (VMs), if known

  std::string advice() const;
  // 1 - CPU / wall median: the share of a run spent waiting for a CPU (or for I/O).
  double waiting_fraction() const;
};

// Above this waiting fraction the doctor says that runs queue for a CPU.
inline constexpr double kWaitingWarnFraction = 0.1;

// Pure: the statistics of measured rounds. Throws std::invalid_argument for fewer than 2 rounds
// or a time that is not positive.
NoiseScore summarize_noise(std::span<const NoiseRound> rounds);

struct NoiseOptions {
  std::filesystem::path baseline;  // raygate-baseline
  int rounds = kDefaultNoiseRounds;
  std::filesystem::path work_dir;                             // scene and run files go here
  std::filesystem::path root = "/";                           // for /proc/stat (steal time)
  std::filesystem::path idle_poll_device{kCpuLatencyDevice};  // runner/idle_poll.h
};

// The fixed scene: SPD balls at size 3, 128x128 (820 spheres; about 0.1 s per run on a current
// core with --accel none), long enough that timer resolution does not matter.
SuiteScene noise_scene();

// Generates the scene, runs one warm-up and then `rounds` A/A pairs. Throws InfraError when the
// baseline cannot run or writes no usable statistics; UsageError for rounds < 2.
NoiseScore measure_noise(const NoiseOptions& options);

}  // namespace raygate

// Synthetic timings for the measure tests, drawn from raygate's own PRNG so that every machine
// generates the same "random" experiments and the tests are exact and stable.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "measure/change.h"
#include "measure/random.h"
#include "measure/ratio.h"

namespace raygate::testing {

// Standard normal by Box-Muller (one of the pair; simplicity over speed).
inline double standard_normal(Xoshiro256& rng) {
  const double u1 = 1.0 - rng.uniform_unit();  // in (0, 1]: log is finite
  const double u2 = rng.uniform_unit();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

// Rounds whose log-ratio is Normal(ln true_ratio, log_sigma); the baseline itself drifts by
// up to +-20% between rounds, as a busy CI runner would, which the ratio must cancel.
inline std::vector<RoundSample> ratio_rounds(Xoshiro256& rng, int count, double true_ratio,
                                             double log_sigma) {
  std::vector<RoundSample> rounds;
  for (int i = 0; i < count; ++i) {
    const double machine_speed = 1.0 + 0.2 * std::sin(i * 0.7);
    const double baseline_seconds = 1.5 * machine_speed;
    const double log_ratio = std::log(true_ratio) + log_sigma * standard_normal(rng);
    rounds.push_back({baseline_seconds * std::exp(log_ratio), baseline_seconds});
  }
  return rounds;
}

// Rounds of (baseline, base, head) where head = base * true_factor, each revision's time with
// independent log-normal noise of log_sigma, and a drift common to the whole round.
inline std::vector<CompareRound> compare_rounds(Xoshiro256& rng, int count, double true_factor,
                                                double log_sigma) {
  std::vector<CompareRound> rounds;
  for (int i = 0; i < count; ++i) {
    const double machine_speed = 1.0 + 0.2 * std::sin(i * 0.7);
    CompareRound round;
    round.baseline_seconds = 1.5 * machine_speed * std::exp(log_sigma * standard_normal(rng));
    round.base_seconds = 3.0 * machine_speed * std::exp(log_sigma * standard_normal(rng));
    round.head_seconds =
        3.0 * true_factor * machine_speed * std::exp(log_sigma * standard_normal(rng));
    rounds.push_back(round);
  }
  return rounds;
}

}  // namespace raygate::testing

// Simulated compare rounds with the noise this project's 2-core VM shows (README, "How reliable
// is the gate?"): every run off by a few percent, single runs up to +35% (the host stealing the
// CPU), and bursts of +35% lasting several runs. Runs are simulated in time order with the
// rotating (baseline, base, head) order of a compare, so a burst that starts mid-round slows
// whichever revision ran in it: the skewed, serially dependent noise the gate must live with.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "measure/change.h"
#include "measure/random.h"
#include "synthetic.h"

namespace raygate::testing {

struct VmNoise {
  double log_sigma = 0.03;           // every run: log-normal, about +-6% at 2 sigma
  double spike_chance = 0.05;        // a single run slowed by 10-35%
  double burst_start_chance = 0.02;  // per run: a burst of 3-8 runs, each +35%
};

class VmRounds {
 public:
  VmRounds(std::uint64_t seed, VmNoise noise) : rng_(seed), noise_(noise) {}

  // The next round, head = base * true_factor before noise; with `repeats`, each role runs that
  // many times, interleaved (baseline, base, head, baseline, ...), and keeps its fastest run, as
  // ScheduleOptions::repeats does.
  CompareRound next(double true_factor, int repeats = 1) {
    const double nominal[3] = {1.0, 2.0, 2.0 * true_factor};  // baseline, base, head
    double seconds[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL};
    const int first = static_cast<int>(round_ % 3);
    for (int r = 0; r < repeats; ++r) {
      for (int k = 0; k < 3; ++k) {
        const int role = (first + k) % 3;
        seconds[role] = std::min(seconds[role], nominal[role] * slowdown());
      }
    }
    ++round_;
    return {seconds[0], seconds[1], seconds[2]};
  }

 private:
  double slowdown() {
    if (burst_left_ == 0 && rng_.uniform_unit() < noise_.burst_start_chance) {
      burst_left_ = 3 + static_cast<int>(rng_.uniform_below(6));
    }
    double factor = std::exp(noise_.log_sigma * standard_normal(rng_));
    if (burst_left_ > 0) {
      factor *= 1.35;
      --burst_left_;
    }
    if (rng_.uniform_unit() < noise_.spike_chance) factor *= 1.10 + 0.25 * rng_.uniform_unit();
    return factor;
  }

  Xoshiro256 rng_;
  VmNoise noise_;
  std::uint64_t round_ = 0;
  int burst_left_ = 0;
};

}  // namespace raygate::testing

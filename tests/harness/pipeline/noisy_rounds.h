// Hand-made rounds for the tests of the fastest-of-two choices (pipeline/visit_plan.h for
// compare, pipeline/ratio_repeats.h for run): a round's two timed roles, the one in the
// denominator (base, or the baseline) and the one in the numerator (head, or the tracer).
#pragma once

#include <string>
#include <vector>

#include "runner/scheduler.h"

namespace raygate::testing {

struct TimedRoles {
  std::string denominator;
  std::string numerator;
};

inline const TimedRoles kBaseHead{"base", "head"};
inline const TimedRoles kBaselineTracer{"baseline", "tracer"};

// A round in which each role ran `runs_each` times (its order says so) and kept these seconds.
inline Round round_of(const TimedRoles& roles, double denominator_seconds, double numerator_seconds,
                      int runs_each = 1) {
  Round round;
  for (int k = 0; k < runs_each; ++k) {
    round.order.push_back(roles.denominator);
    round.order.push_back(roles.numerator);
  }
  round.runs[roles.denominator].seconds = denominator_seconds;
  round.runs[roles.numerator].seconds = numerator_seconds;
  return round;
}

// Of each adjacent pair of one-run rounds, the first's numerator and the second's denominator
// slowed by 4-14% (the host took the CPU): one run per round spreads by several percent, the
// fastest of two hardly at all.
inline std::vector<Round> one_sided_noise(const TimedRoles& roles, int pairs) {
  std::vector<Round> rounds;
  for (int k = 0; k < pairs; ++k) {
    rounds.push_back(round_of(roles, 1.0, 1.04 + 0.02 * (k % 6)));
    rounds.push_back(round_of(roles, 1.14 - 0.02 * (k % 6), 1.0 + 0.001 * (k % 3)));
  }
  return rounds;
}

}  // namespace raygate::testing

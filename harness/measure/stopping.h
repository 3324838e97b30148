// When to stop adding rounds for a scene (DESIGN.md §6): as soon as the normalized ratio is known
// to the target precision, or when the budget is spent. Pure functions of the rounds so far, so
// the runner's loop stays trivial and the rule is tested without timing anything.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

#include "measure/bootstrap.h"
#include "measure/ratio.h"

namespace raygate {

struct StoppingPolicy {
  double target_relative_half_width = 0.01;  // stop once the 95% CI is within +-1% of the ratio
  std::size_t min_rounds = 3;    // below this the bootstrap CI is too coarse to trust
  std::size_t max_rounds = 30;   // per scene
  double max_seconds = 300.0;    // per scene, wall time of all its runs so far
};

enum class StopDecision {
  continue_measuring,
  stop_converged,
  stop_budget_rounds,
  stop_budget_time,
};

std::string_view to_string(StopDecision decision);

// The rule on numbers: converged wins over a budget that ran out in the same round (the result
// is good either way, and "converged" is the more useful thing to report); then rounds, then time.
StopDecision decide_stopping(std::size_t rounds, double relative_half_width,
                             const StoppingPolicy& policy, double seconds_spent);

// The rule on samples: summarizes them (bootstrap CI) when there are at least min_rounds.
StopDecision decide_stopping(std::span<const RoundSample> rounds, const StoppingPolicy& policy,
                             double seconds_spent, const BootstrapOptions& options = {});

}  // namespace raygate

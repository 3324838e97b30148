// When to stop adding rounds for a scene (DESIGN.md §6): the one stopping policy of run, compare
// and bisect. A rule in two parts, kept apart on purpose:
//  - a verdict function answers "is this scene's question decided by its rounds so far?" (run:
//    the ratio is known to the target precision; compare and bisect: the change's verdict is no
//    longer INCONCLUSIVE). A new way of deciding (a sequential test, a deterministic timing mode
//    that is decided after one round) is a new verdict function, nothing else.
//  - should_stop() turns a verdict and the budget (rounds, seconds) into a StopDecision.
// Pure functions of the rounds so far, so the runner's loop stays trivial and the rule is tested
// without timing anything. pipeline/stop_rules.h binds them to a scene's rounds.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

#include "measure/bootstrap.h"
#include "measure/change.h"
#include "measure/ratio.h"

namespace raygate {

// The defaults of --target, --min-rounds, --max-rounds, --max-seconds and --max-minutes: here
// (and in change_stopping_policy() below) and nowhere else.
struct StoppingPolicy {
  double target_relative_half_width = 0.01;  // stop once the 95% CI is within +-1% of the ratio
  // Below 6 rounds no interval of the sample covers the median with 95% (measure/
  // median_interval.h: the range of n rounds covers it with 1 - 2 * 0.5^n, 75% for 3), and a
  // bootstrap "95% CI" of 3 rounds is their range: an identity tracer's ratio stopped
  // "converged" at 1.025 [1.024, 1.036] after 3 rounds.
  std::size_t min_rounds = 6;
  std::size_t max_rounds = 30;  // per scene
  double max_seconds = 300.0;   // per scene, wall time of all its runs so far
  // The whole measurement, shared by the scenes in order (measure/compare_budget.h); 0 = none.
  double max_minutes = 0.0;
};

// The defaults of compare and bisect. Their verdicts come from confidence sequences, which stay
// unbounded for the first 7-14 rounds (docs/statistics.md §6a), and a round without the
// baseline costs only base and head, so a scene near its limit may take 300 rounds; the whole
// compare is bounded instead, by 8 minutes, so a full `ci` compare fits a 10-minute CI step.
StoppingPolicy change_stopping_policy();

// The rounds of a compare or bisect scene the baseline joins: the change needs none (the
// baseline cancels within a round), each revision's normalized ratio a few; more would spend
// most of a fast tracer's compare timing a program outside the verdict. Three make the ratio's
// interval their range, a 75% interval; a scene whose rounds say a few more would make its
// stored ratio precise gets them as ratio rounds once the scenes are decided
// (pipeline/stored_ratio.h). Six in every scene cost nff-tracer's compare about 70 s more on
// this VM (2026-11-28) and made no ratio precise there.
inline constexpr std::size_t kChangeBaselineRounds = 3;

// The longest a single run may take within `policy`'s budget: its own limit `own_seconds`, but
// never past the seconds a scene may use (max_seconds) or the whole measurement
// (max_minutes), so a hanging program cannot outlive the budget the user gave.
double budgeted_run_seconds(const StoppingPolicy& policy, double own_seconds);

enum class StopDecision {
  continue_measuring,
  stop_converged,
  stop_budget_rounds,
  stop_budget_time,
};

std::string_view to_string(StopDecision decision);

// What the rule knows after a round.
struct StoppingState {
  std::size_t rounds = 0;      // complete rounds of the scene
  double seconds_spent = 0.0;  // wall time of all its runs so far
  bool decided = false;        // the verdict function's answer on those rounds
};

// The rule: decided wins over a budget that ran out in the same round (the result is good
// either way, and "converged" is the more useful thing to report); then rounds, then time.
StopDecision should_stop(const StoppingState& state, const StoppingPolicy& policy);

// The fewest rounds a statistical verdict decides on: min_rounds, and never one (one round's
// interval is a point, which would always look decided).
std::size_t rounds_to_decide(const StoppingPolicy& policy);

// Verdict of `run`: the ratio's CI half-width is within the target, on rounds_to_decide() rounds
// or more.
bool ratio_decided(std::span<const RoundSample> rounds, const StoppingPolicy& policy,
                   const BootstrapOptions& options = {});

// Verdict of `compare` and `bisect`: the change of head against base is REGRESSED, IMPROVED or
// UNCHANGED at `max_slowdown` (not INCONCLUSIVE) on its confidence sequences at `levels`, on
// rounds_to_decide() rounds or more. The sequences are valid at every round, so asking after each
// one costs no error (docs/statistics.md §6a). `counted` (sim mode): rounds whose counts all
// repeat decide exactly, without a sequence (measure/simulated_cost.h).
bool change_decided(std::span<const CompareRound> rounds, const StoppingPolicy& policy,
                    double max_slowdown, const BootstrapOptions& options,
                    const SequenceLevels& levels, bool counted = false);

// The rule on a ratio's numbers (converged: at least min_rounds and the half-width within the
// target), for callers that already summarized the rounds.
StopDecision decide_stopping(std::size_t rounds, double relative_half_width,
                             const StoppingPolicy& policy, double seconds_spent);

// The rule on samples: summarizes them (order-statistic CI) when there are at least min_rounds.
StopDecision decide_stopping(std::span<const RoundSample> rounds, const StoppingPolicy& policy,
                             double seconds_spent, const BootstrapOptions& options = {});

}  // namespace raygate

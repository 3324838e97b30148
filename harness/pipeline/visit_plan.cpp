#include "pipeline/visit_plan.h"

#include <algorithm>
#include <limits>
#include <optional>
#include <vector>

#include "measure/change.h"
#include "measure/fastest_of_two.h"
#include "runner/scheduler.h"

namespace raygate {
namespace {

// Seconds of one run per side and round: the scene's seconds so far over the runs it made, so
// warm-ups and the baseline's rounds are spread over them as they will be in later rounds.
double seconds_per_run(const SceneRuns& runs) {
  std::size_t count = 0;
  for (const Round& round : runs.rounds) count += runs_per_contender(round);
  return count == 0 ? 0.0 : runs.seconds_spent / static_cast<double>(count);
}

// A scene's rounds by how they ran: each contender once, or its fastest of two (or more).
struct RoundsByRuns {
  std::vector<Round> one_run;
  std::vector<Round> repeated;
};

RoundsByRuns split_by_runs(const SceneRuns& runs) {
  RoundsByRuns split;
  for (const Round& round : runs.rounds) {
    (runs_per_contender(round) >= 2 ? split.repeated : split.one_run).push_back(round);
  }
  return split;
}

// The spread of the scene's rounds with each side's fastest of two: measured, over the rounds
// that repeated, once there are enough of them; else projected from pairs of one-run rounds.
std::optional<double> spread_with_fastest_of_two(const RoundsByRuns& rounds) {
  if (rounds.repeated.size() >= 2 * kMinPairsForSpread) {
    return quartile_spread(compare_log_changes(compare_samples(rounds.repeated)));
  }
  return fastest_of_two_spread(compare_samples(rounds.one_run));
}

// The spread of one-run rounds to come, once the scene also has repeated ones (whose steadier
// rounds would otherwise make one run look better than it is): the one-run rounds' own.
// nullopt while every round ran once: the rounds so far are the one-run rounds.
std::optional<double> spread_with_one_run(const RoundsByRuns& rounds) {
  if (rounds.repeated.empty() || rounds.one_run.empty()) return std::nullopt;
  return quartile_spread(compare_log_changes(compare_samples(rounds.one_run)));
}

double seconds_for(std::optional<std::size_t> needed, std::size_t rounds,
                   double seconds_per_round) {
  if (!needed) return std::numeric_limits<double>::infinity();
  return seconds_per_round * static_cast<double>(*needed > rounds ? *needed - rounds : 0);
}

// The scene's change with the spread of its rounds from their quartiles: on one-sided noise the
// MAD sees only the steady rounds and promises a verdict the slowed ones keep away
// (measure/fastest_of_two.h).
ChangeSummary projected_change(const SceneRuns& runs, const ChangeSummary& change) {
  ChangeSummary projected = change;
  if (!projected.exact && !runs.rounds.empty()) {
    projected.log_change_mad_scaled =
        quartile_spread(compare_log_changes(compare_samples(runs.rounds)));
  }
  return projected;
}

}  // namespace

std::optional<std::size_t> rounds_to_decide(const SceneResult& scene, double threshold) {
  if (!scene.change) return std::nullopt;
  return estimated_rounds_to_decide(projected_change(scene.runs, *scene.change), threshold,
                                    spread_with_one_run(split_by_runs(scene.runs)));
}

VisitPlan plan_visit(const SceneResult& scene, const GatePolicy& gate_policy, bool may_repeat) {
  if (!scene.change) return {};
  return plan_rounds(scene.runs, *scene.change, gate_policy.for_scene(scene.entry.id).max_slowdown,
                     may_repeat);
}

std::size_t next_round_repeats(const SceneRuns& so_far, const ChangeSummary& change,
                               double threshold) {
  if (so_far.rounds.size() < 2 * kMinPairsForSpread) return 1;
  return std::max<std::size_t>(plan_rounds(so_far, change, threshold, true).repeats, 1);
}

VisitPlan plan_rounds(const SceneRuns& runs, const ChangeSummary& change, double threshold,
                      bool may_repeat) {
  VisitPlan plan;
  const std::size_t rounds = runs.rounds.size();
  if (rounds == 0) return plan;
  const double run_seconds = seconds_per_run(runs);
  const ChangeSummary projected = projected_change(runs, change);
  const RoundsByRuns split = split_by_runs(runs);
  plan.seconds =
      seconds_for(estimated_rounds_to_decide(projected, threshold, spread_with_one_run(split)),
                  rounds, run_seconds);
  if (!may_repeat || projected.exact) return plan;
  const std::optional<double> spread = spread_with_fastest_of_two(split);
  if (!spread) return plan;
  const double repeated_seconds = seconds_for(
      estimated_rounds_to_decide(projected, threshold, *spread), rounds, 2.0 * run_seconds);
  if (repeated_seconds < kFastestOfTwoMustSave * plan.seconds) {
    plan.seconds = repeated_seconds;
    plan.repeats = 2;
  } else {
    plan.repeats = 1;
  }
  return plan;
}

}  // namespace raygate

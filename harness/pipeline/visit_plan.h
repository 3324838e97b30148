// How the second pass of a compare plans a scene's next visit (pipeline/measurement_plan.h,
// MeasurementPlan::plan_visit): about how many seconds more the scene needs, at the pace of its rounds so far,
// and whether it gets there sooner with each side's fastest of two runs per round.
#pragma once

#include <cstddef>
#include <optional>

#include "gate/policy.h"
#include "pipeline/measurement_plan.h"
#include "results/results.h"

namespace raygate {

// The next visit of `scene`, left INCONCLUSIVE by its share of the time: its estimated rounds
// (measure/change.h, estimated_rounds_to_decide, projected from the rounds' quartile_spread)
// times its seconds per round. With
// `may_repeat` (the measurement's own --repeats was not set), the same for rounds of the
// fastest of two runs per side, projected from their spread (measured in the scene's earlier
// visits, else from pairs of its one-run rounds, measure/fastest_of_two.h) at twice a one-run
// round's seconds; the visit repeats when that saves at least 1 - kFastestOfTwoMustSave.
// Seconds are infinite for a scene without a change or an estimate.
VisitPlan plan_visit(const SceneResult& scene, const GatePolicy& gate_policy, bool may_repeat);

// The same for a scene's rounds `runs` with their `change`, at the scene's slowdown limit
// `threshold`.
VisitPlan plan_rounds(const SceneRuns& runs, const ChangeSummary& change, double threshold,
                      bool may_repeat);

// The first pass's choice before each round of a compare scene (runner/scheduler.h,
// RepeatChooser): one run until the scene has 2 * kMinPairsForSpread rounds, then the fastest of
// two whenever a visit planned now would take it. A scene that will not decide within its
// share reaches the second pass with rounds of the kind that decides it, instead of more of the
// kind that does not.
std::size_t next_round_repeats(const SceneRuns& so_far, const ChangeSummary& change,
                               double threshold);

// About how many rounds in all the scene needs if its rounds go on as they went (the plan's
// one-run projection, from the quartile_spread of its rounds); nullopt as for
// estimated_rounds_to_decide. What compare's INCONCLUSIVE line prints, so the line and the
// second pass agree.
std::optional<std::size_t> rounds_to_decide(const SceneResult& scene, double threshold);

}  // namespace raygate

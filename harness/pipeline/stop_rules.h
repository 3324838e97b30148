// The stopping policy (measure/stopping_policy.h) bound to a scene's rounds: the StopRule the
// scheduler asks after each round, one per measuring command. Both are should_stop() over the
// same budget; they differ only in the verdict function, which is the seam for another way of
// deciding: write a SceneVerdict and pass it to stop_rule(). Also the whole measurement's time
// budget (--max-minutes), which caps each scene's seconds at its share.
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "gate/policy.h"
#include "measure/stopping_policy.h"
#include "runner/executor.h"
#include "runner/scheduler.h"

namespace raygate {

// Is the question this measurement asks of the scene decided by these rounds?
using SceneVerdict = std::function<bool(const std::vector<Round>& rounds)>;

// should_stop() with `verdict`'s answer and the budget of `policy`.
StopRule stop_rule(const StoppingPolicy& policy, SceneVerdict verdict);

// `run`: the normalized ratio of `tracer_role` is known to the target precision.
SceneVerdict ratio_verdict(const StoppingPolicy& policy, Role tracer_role,
                           Role baseline_role = Role::baseline);

// The levels of a compare scene's confidence sequences (docs/statistics.md §6b): the decision
// sequence at `decision_alpha`, the scene's share of the family (measure/family.h); the
// equivalence sequence at the scene's significance; the one-look interval at 1 - significance.
SequenceLevels scene_levels(const ScenePolicy& scene, double decision_alpha);

// `compare` and `bisect`: head's change against base has a verdict other than INCONCLUSIVE at
// the scene's slowdown limit, on its confidence sequences at `levels`. `counted`: sim mode,
// where rounds whose counts all repeat decide exactly.
SceneVerdict change_verdict(const StoppingPolicy& policy, const ScenePolicy& scene,
                            const SequenceLevels& levels, bool counted = false);

// The rules of the commands: stop_rule() with the verdicts above.
StopRule ratio_stop_rule(const StoppingPolicy& policy, Role tracer_role,
                         Role baseline_role = Role::baseline);
StopRule change_stop_rule(const StoppingPolicy& policy, const ScenePolicy& scene,
                          const SequenceLevels& levels, bool counted = false);

// The bootstrap of a compare scene: its confidence is 1 - the scene's significance.
BootstrapOptions change_bootstrap(const ScenePolicy& scene);

// The whole measurement's time budget (StoppingPolicy::max_minutes), spent in two passes.
// The first pass measures the scenes in order, each with what is left divided by the scenes left
// plus `reserve_scenes`, so the time a scene saves by deciding early goes to the scenes after it
// and about reserve / (scenes + reserve) of the budget stays for the second pass. The second
// pass (pipeline/measurement_plan.h, MeasurementPlan::revisit_stop) visits the scenes still undecided, the
// cheapest to decide first, each with what it is estimated to need and a margin
// (kRevisitMargin), estimated anew after every visit (and doubled for each visit it outlived),
// until the time is gone. Given in that
// order, the time decides the most scenes it can: an even share would stop each a round or two
// short of a verdict, or let one scene that needs more than its estimate keep time the scenes
// after it could have decided with. A scene that decides in the first pass costs no more than
// before.
class SuiteBudget {
 public:
  SuiteBudget(const StoppingPolicy& policy, std::size_t scenes, Clock& clock,
              std::size_t reserve_scenes = 0);
  // The stopping policy of the next scene of the first pass: `policy` with max_seconds capped
  // at its share.
  StoppingPolicy next_scene();
  // The stopping policy of a further visit to a scene that has used `seconds_spent` so far,
  // estimated to need `seconds_to_decide` more: max_seconds is its seconds so far plus
  // kRevisitMargin times its estimate, never more than what is left (the scheduler counts every
  // visit's seconds). With no estimate (infinity: a change on the limit) an even share of what
  // is left among the `scenes_left` undecided scenes (this one included).
  StoppingPolicy again(double seconds_spent, std::size_t scenes_left,
                       double seconds_to_decide = std::numeric_limits<double>::infinity()) const;

 private:
  StoppingPolicy policy_;
  std::size_t scenes_left_;
  std::size_t reserve_scenes_;
  Clock& clock_;
  double started_;
};

// A revisited scene's estimate (measure/change.h estimated_rounds_to_decide) is projected from a
// few rounds' spread, and at the least the rounds its interval needs to be bounded at all: give
// half as much again, so a scene estimated a round short gets that round.
inline constexpr double kRevisitMargin = 1.5;

// How many scenes' worth of a compare's budget the first pass keeps for the second: a quarter
// of the scenes, rounded up (4 of the ci suite's 13), none for a single scene.
std::size_t revisit_reserve_scenes(std::size_t scenes);

}  // namespace raygate

// The stopping policy (measure/stopping.h) bound to a scene's rounds: the StopRule the
// scheduler asks after each round, one per measuring command. Both are should_stop() over the
// same budget; they differ only in the verdict function, which is the seam for another way of
// deciding: write a SceneVerdict and pass it to stop_rule().
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gate/policy.h"
#include "measure/stopping.h"
#include "runner/scheduler.h"

namespace raygate {

// Is the question this measurement asks of the scene decided by these rounds?
using SceneVerdict = std::function<bool(const std::vector<Round>& rounds)>;

// should_stop() with `verdict`'s answer and the budget of `policy`.
StopRule stop_rule(const StoppingPolicy& policy, SceneVerdict verdict);

// `run`: the normalized ratio of `tracer_role` is known to the target precision.
SceneVerdict ratio_verdict(const StoppingPolicy& policy, const std::string& tracer_role,
                           const std::string& baseline_role = "baseline");

// `compare` and `bisect`: head's change against base has a verdict other than INCONCLUSIVE at
// the scene's slowdown limit and significance. `counted`: sim mode, where rounds whose counts all
// repeat decide exactly.
SceneVerdict change_verdict(const StoppingPolicy& policy, const ScenePolicy& scene,
                            bool counted = false);

// The rules of the commands: stop_rule() with the verdicts above.
StopRule ratio_stop_rule(const StoppingPolicy& policy, const std::string& tracer_role,
                         const std::string& baseline_role = "baseline");
StopRule change_stop_rule(const StoppingPolicy& policy, const ScenePolicy& scene,
                          bool counted = false);

// The bootstrap of a compare scene: its confidence is 1 - the scene's significance.
BootstrapOptions change_bootstrap(const ScenePolicy& scene);

}  // namespace raygate

// Judged like a scene's speed change (measure/change.h classify_change), with the exponent
// change and its interval in place of the relative change and the exponent limit in place of
// max_slowdown: REGRESSED fails, INCONCLUSIVE warns (or fails with fail_on_inconclusive).
#include "gate/growth_gate.h"

#include <fmt/core.h>

#include "scaling/scaling_text.h"

namespace raygate {

ScalingLimits scaling_limits(const GatePolicy& policy) {
  return {policy.max_exponent_increase, policy.defaults.max_slowdown};
}

std::vector<SceneGate> judge_growth(const ResultsDocument& document, const GatePolicy& policy) {
  std::vector<SceneGate> gates;
  if (!document.scaling) return gates;
  for (const FamilyScaling& family : document.scaling->families) {
    if (!family.change) continue;
    ExponentChange change = *family.change;
    change.limit = policy.max_exponent_increase;
    change.verdict = judge_exponent(change);
    SceneGate gate;
    gate.id = "scaling:" + family.family;
    gate.speed = speed_verdict(change.verdict);
    if (change.verdict == ChangeVerdict::regressed) {
      gate.outcome = GateOutcome::fail;
    } else if (change.verdict == ChangeVerdict::inconclusive) {
      gate.outcome = policy.fail_on_inconclusive ? GateOutcome::fail : GateOutcome::warn;
    }
    gate.speed_outcome = gate.outcome;
    if (gate.outcome != GateOutcome::pass) {
      gate.reasons.push_back(
          fmt::format("{} growth: {}", family.family, describe_change(family.family, change)));
    }
    gates.push_back(std::move(gate));
  }
  return gates;
}

}  // namespace raygate

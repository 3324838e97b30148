// The complexity gate's verdicts (docs/scaling.md): for a compare whose document carries a
// scaling analysis, each scene family's change of growth exponent judged against the policy's
// max_exponent_increase, so `raygate gate` with another policy judges the stored fits again.
#pragma once

#include <vector>

#include "gate/policy.h"
#include "gate/verdict.h"
#include "scaling/scaling_analysis.h"
#include "results/results.h"

namespace raygate {

// One SceneGate per family with a base/head exponent change, id "scaling:<family>", speed the
// exponent verdict; none for a run or a document without a scaling analysis.
// The policy's limits the scaling analysis projects with.
ScalingLimits scaling_limits(const GatePolicy& policy);

std::vector<SceneGate> judge_growth(const ResultsDocument& document, const GatePolicy& policy);

}  // namespace raygate

// The complexity gate (docs/scaling.md): the scenes of a results document grouped by SPD scene
// family, each family's growth exponent fitted for the baseline, each tracer role and its
// normalized ratio, and for a compare the change of exponent from base to head, judged against
// the policy's limit and projected to the sizes where it would cost more than the speed limit.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "measure/change.h"
#include "results/scaling_record.h"
#include "scaling/power_fit.h"
#include "results/results.h"

namespace raygate {

struct ScalingLimits {
  double max_exponent_increase = 0.1;
  double max_slowdown = 0.03;
};

// Primitives of an SPD scene at a size factor (scaling/primitive_count.h; tests inject counts).
using PrimitiveCounter = std::function<std::int64_t(const std::string& scene, int size)>;

// Families with fewer than 3 measured sizes are left out: a line through two points has no
// error to report. Failed scenes are left out of their family.
ScalingAnalysis analyse_scaling(const ResultsDocument& document, const ScalingLimits& limits,
                                const PrimitiveCounter& count);

// The verdict on change.judged()'s exponent and interval under change.limit, as a speed change
// is judged (measure/change.h classify_change); INCONCLUSIVE without an interval.
ChangeVerdict judge_exponent(const ExponentChange& change);

// The worst exponent change: REGRESSED outranks INCONCLUSIVE outranks the rest; nullopt when
// the analysis has no compare.
std::optional<ChangeVerdict> worst_exponent_verdict(const ScalingAnalysis& analysis);

}  // namespace raygate

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
#include "scaling/power_fit.h"
#include "results/results.h"

namespace raygate {

struct ScalingPoint {
  std::string scene_id;
  int size = 0;
  std::int64_t primitives = 0;
  double baseline_seconds = 0.0;          // median over rounds
  std::map<std::string, double> seconds;  // by role (tracer; base, head): median over rounds
  std::map<std::string, double> ratios;   // by role: the normalized ratio
  std::optional<double> change;           // compare: head against base, +0.05 = 5% slower
  std::optional<Interval> change_interval;  // compare: its 95% interval (measure/change.h)
};

struct RoleScaling {
  PowerFit time;   // the role's seconds
  PowerFit ratio;  // its normalized ratio: exponent = the role's minus the baseline's
};

// Where head's projected time exceeds base's by a given fraction.
struct Projection {
  int size = 0;  // SPD size factor
  std::int64_t primitives = 0;
  double change = 0.0;  // projected head / base - 1
};

struct ExponentChange {
  PowerFit fit;  // ln(head / base) on ln n: the exponent is head's minus base's, paired per size
  // When `fit` is not a power law (typically head/base flat at the small sizes, rising at the
  // large ones, as when a fixed cost hides added linear work): the local exponent change between the
  // two largest sizes, the slope that extrapolates, judged and projected instead. Its interval
  // comes from the two sizes' measured change intervals (the widest slope they allow), not from
  // the residuals of a line, which here measure the curve rather than the noise.
  std::optional<PowerFit> large_end;
  ChangeVerdict verdict = ChangeVerdict::inconclusive;
  double limit = 0.0;     // the policy's max_exponent_increase
  double slowdown = 0.0;  // the speed limit the projection is about (policy max_slowdown)
  std::optional<Projection> crossing;  // the smallest SPD size beyond the limit; none: never
  std::optional<Projection> largest;   // at the family's largest SPD size

  const PowerFit& judged() const { return large_end ? *large_end : fit; }
};

struct FamilyScaling {
  std::string family;     // the SPD generator
  std::string series_id;  // of the family's sizes for the measured revision (results/series.h)
  std::vector<ScalingPoint> points;  // by size
  PowerFit baseline;
  std::map<std::string, RoleScaling> roles;
  std::optional<ExponentChange> change;
};

struct ScalingAnalysis {
  std::vector<FamilyScaling> families;  // those with >= 3 sizes measured, in suite order
  double max_exponent_increase = 0.0;
};

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

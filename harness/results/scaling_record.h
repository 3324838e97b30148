// The growth exponents of a results document (its `scaling` member, docs/scaling.md): per scene
// family, power-law fits of time on primitive count for the baseline and each role, and for a
// compare the change of exponent from base to head with its verdict. Value types only: scaling/
// fits them (scaling/power_fit.h, scaling_analysis.h); the gate, the reports and the store read
// them from the document, parsed once at the JSON boundary (results/scaling_json.cpp), without
// depending on scaling/.
#pragma once

#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/domain.h"
#include "measure/bootstrap.h"
#include "measure/change.h"

namespace raygate {

enum class FitQuality {
  power_law,          // the points lie along one line in log-log: the exponent describes them
  startup_dominated,  // the small sizes sit above the line: a fixed cost hides the growth there
  curved,             // the slope changes along the range (not a fixed cost): the exponent averages
  scattered,          // r² < 0.9 with no pattern: too noisy for the exponent to mean much
  too_few_points,     // fewer than 3 sizes: no interval, no diagnosis
};

std::string_view to_string(FitQuality quality);
// nullopt for a word that names no quality.
std::optional<FitQuality> parse_fit_quality(std::string_view text);

// t ≈ c·n^k fitted in log-log (scaling/power_fit.h fit_power_law).
struct PowerFit {
  int points = 0;
  double exponent = 0.0;       // k, the slope in log-log
  Interval exponent_interval;  // 95%, Student's t with points - 2 degrees of freedom
  double log_prefactor = 0.0;  // ln c, the intercept
  double r_squared = 0.0;
  FitQuality quality = FitQuality::too_few_points;
  // Slope over the smallest and over the largest three sizes: how the local exponent moves.
  double small_end_exponent = 0.0;
  double large_end_exponent = 0.0;
  // t = a + b·n^k fitted when the small sizes sit above the line: a is the fixed cost (seconds)
  // and k the growth once it no longer dominates. 0 and the plain exponent when not fitted.
  double fixed_cost = 0.0;
  double growth_exponent = 0.0;

  double predict(double primitives) const {
    return std::exp(log_prefactor + exponent * std::log(primitives));
  }
};

struct ScalingPoint {
  std::string scene_id;
  int size = 0;
  std::int64_t primitives = 0;
  double baseline_seconds = 0.0;            // median over rounds
  std::map<Role, double> seconds;           // by role (tracer; base, head): median over rounds
  std::map<Role, double> ratios;            // by role: the normalized ratio
  std::optional<double> change;             // compare: head against base, +0.05 = 5% slower
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
  std::map<Role, RoleScaling> roles;
  std::optional<ExponentChange> change;
};

struct ScalingAnalysis {
  std::vector<FamilyScaling> families;  // those with >= 3 sizes measured, in suite order
  double max_exponent_increase = 0.0;
};

}  // namespace raygate

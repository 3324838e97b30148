// How run time grows with scene size: a least-squares fit of ln(seconds) on ln(primitives), whose
// slope is the growth exponent k of t ≈ c·n^k, with its 95% confidence interval and a diagnosis
// of when a power law does not describe the points (docs/scaling.md).
#pragma once

#include <span>
#include <string_view>

#include "measure/bootstrap.h"

namespace raygate {

struct SizePoint {
  double primitives = 0.0;  // n: primitives in the scene
  double value = 0.0;       // seconds, or a ratio of seconds; positive
};

enum class FitQuality {
  power_law,          // the points lie along one line in log-log: the exponent describes them
  startup_dominated,  // the small sizes sit above the line: a fixed cost hides the growth there
  curved,             // the slope changes along the range (not a fixed cost): the exponent averages
  scattered,          // r² < 0.9 with no pattern: too noisy for the exponent to mean much
  too_few_points,     // fewer than 3 sizes: no interval, no diagnosis
};

struct PowerFit {
  int points = 0;
  double exponent = 0.0;         // k, the slope in log-log
  Interval exponent_interval;    // 95%, Student's t with points - 2 degrees of freedom
  double log_prefactor = 0.0;    // ln c, the intercept
  double r_squared = 0.0;
  FitQuality quality = FitQuality::too_few_points;
  // Slope over the smallest and over the largest three sizes: how the local exponent moves.
  double small_end_exponent = 0.0;
  double large_end_exponent = 0.0;
  // t = a + b·n^k fitted when the small sizes sit above the line: a is the fixed cost (seconds)
  // and k the growth once it no longer dominates. 0 and the plain exponent when not fitted.
  double fixed_cost = 0.0;
  double growth_exponent = 0.0;

  double predict(double primitives) const;
};

// Throws std::invalid_argument for a point whose primitives or value is not positive and finite.
// Points may come in any order; equal primitive counts are allowed but need 2 distinct ones.
PowerFit fit_power_law(std::span<const SizePoint> points);

// The 0.975 quantile of Student's t with `dof` degrees of freedom (dof >= 1).
double student_t_975(int dof);

std::string_view to_string(FitQuality quality);
// Throws std::invalid_argument naming the text for an unknown quality.
FitQuality fit_quality_from_string(std::string_view text);

}  // namespace raygate

// How run time grows with scene size: a least-squares fit of ln(seconds) on ln(primitives), whose
// slope is the growth exponent k of t ≈ c·n^k, with its 95% confidence interval and a diagnosis
// of when a power law does not describe the points (docs/scaling.md).
#pragma once

#include <span>
#include <string_view>

#include "measure/bootstrap.h"
#include "results/scaling_record.h"  // PowerFit, FitQuality: the record a fit makes

namespace raygate {

struct SizePoint {
  double primitives = 0.0;  // n: primitives in the scene
  double value = 0.0;       // seconds, or a ratio of seconds; positive
};

// Throws std::invalid_argument for a point whose primitives or value is not positive and finite.
// Points may come in any order; equal primitive counts are allowed but need 2 distinct ones.
PowerFit fit_power_law(std::span<const SizePoint> points);

// The 0.975 quantile of Student's t with `dof` degrees of freedom (dof >= 1).
double student_t_975(int dof);

}  // namespace raygate

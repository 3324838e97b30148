// Descriptive statistics of one sample of doubles (run times, log-ratios). Every function works
// on a copy or reads only, so callers keep their samples in measurement order. An empty sample
// is a programming error here (the caller decides what "no rounds" means) and throws
// std::invalid_argument.
#pragma once

#include <span>

namespace raygate {

// Scale that turns the raw MAD into a consistent estimator of the standard deviation for normal
// data: 1 / Phi^-1(3/4).
inline constexpr double kMadNormalScale = 1.482602218505602;

double median(std::span<const double> values);

// Quantile at probability p in [0, 1], Hyndman and Fan definition 7 (R's default, numpy's
// "linear"): with the sample sorted as x[0..n-1] and h = (n - 1) p, the value
// x[floor h] + (h - floor h) (x[floor h + 1] - x[floor h]).
double quantile(std::span<const double> values, double p);

// Median absolute deviation from the median, raw: median |x_i - median(x)|.
double mad_raw(std::span<const double> values);
// kMadNormalScale * mad_raw: comparable to a standard deviation. This is the one reports show.
double mad_scaled(std::span<const double> values);

double mean(std::span<const double> values);
// Sample standard deviation (divisor n - 1); 0 for a single value.
double standard_deviation(std::span<const double> values);
// standard_deviation / mean; throws if the mean is 0.
double coefficient_of_variation(std::span<const double> values);
// exp(mean(ln x)); every value must be positive and finite.
double geometric_mean(std::span<const double> values);

// Median of a sample that is already sorted ascending (no copy); used in hot loops.
double median_of_sorted(std::span<const double> sorted);
// Quantile (definition 7, as above) of a sample that is already sorted ascending.
double quantile_of_sorted(std::span<const double> sorted, double p);

}  // namespace raygate

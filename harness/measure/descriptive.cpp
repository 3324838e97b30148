#include "measure/descriptive.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace raygate {
namespace {

void require_values(std::span<const double> values, const char* function) {
  if (values.empty()) throw std::invalid_argument(std::string(function) + ": empty sample");
}

std::vector<double> sorted_copy(std::span<const double> values) {
  std::vector<double> copy(values.begin(), values.end());
  std::sort(copy.begin(), copy.end());
  return copy;
}

}  // namespace

double median_of_sorted(std::span<const double> sorted) {
  require_values(sorted, "median");
  const std::size_t n = sorted.size();
  const std::size_t mid = n / 2;
  if (n % 2 == 1) return sorted[mid];
  // Midpoint written so that it cannot overflow and is exact for equal neighbours.
  return sorted[mid - 1] + (sorted[mid] - sorted[mid - 1]) / 2.0;
}

double quantile_of_sorted(std::span<const double> sorted, double p) {
  require_values(sorted, "quantile");
  if (!(p >= 0.0 && p <= 1.0)) throw std::invalid_argument("quantile: p must lie in [0, 1]");
  const double h = static_cast<double>(sorted.size() - 1) * p;
  const double floor_h = std::floor(h);
  const auto lower = static_cast<std::size_t>(floor_h);
  if (lower + 1 >= sorted.size()) return sorted.back();
  return sorted[lower] + (h - floor_h) * (sorted[lower + 1] - sorted[lower]);
}

double median(std::span<const double> values) {
  require_values(values, "median");
  return median_of_sorted(sorted_copy(values));
}

double quantile(std::span<const double> values, double p) {
  require_values(values, "quantile");
  return quantile_of_sorted(sorted_copy(values), p);
}

double mad_raw(std::span<const double> values) {
  const double center = median(values);
  std::vector<double> deviations;
  deviations.reserve(values.size());
  for (double x : values) deviations.push_back(std::fabs(x - center));
  return median(deviations);
}

double mad_scaled(std::span<const double> values) { return kMadNormalScale * mad_raw(values); }

double mean(std::span<const double> values) {
  require_values(values, "mean");
  double sum = 0.0;
  for (double x : values) sum += x;
  return sum / static_cast<double>(values.size());
}

double standard_deviation(std::span<const double> values) {
  const double center = mean(values);
  if (values.size() < 2) return 0.0;
  // Two-pass: the sum of squared deviations, not E[x^2] - E[x]^2, which cancels badly for run
  // times that differ in the fourth digit.
  double squares = 0.0;
  for (double x : values) squares += (x - center) * (x - center);
  return std::sqrt(squares / static_cast<double>(values.size() - 1));
}

double coefficient_of_variation(std::span<const double> values) {
  const double center = mean(values);
  if (center == 0.0) throw std::invalid_argument("coefficient_of_variation: mean is 0");
  return standard_deviation(values) / center;
}

double geometric_mean(std::span<const double> values) {
  require_values(values, "geometric_mean");
  double log_sum = 0.0;
  for (double x : values) {
    if (!(x > 0.0) || !std::isfinite(x)) {
      throw std::invalid_argument("geometric_mean: values must be positive and finite");
    }
    log_sum += std::log(x);
  }
  return std::exp(log_sum / static_cast<double>(values.size()));
}

}  // namespace raygate

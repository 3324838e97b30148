#include "measure/confidence_sequence.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace raygate {
namespace {

void validate(double alpha_each_side) {
  if (!(alpha_each_side > 0.0 && alpha_each_side < 0.5)) {
    throw std::invalid_argument("confidence sequence: alpha per side must lie in (0, 0.5)");
  }
}

// The ranks (1-based) of the interval's ends: lo = the smallest integer above n/2 - b, hi = one
// past the largest integer below n/2 + b. Finite when 1 <= lo and hi <= n.
struct Ranks {
  long lo = 0;
  long hi = 0;
};

Ranks sequence_ranks(std::size_t n, double alpha_each_side) {
  const double b = median_sequence_boundary(n, alpha_each_side, sequence_rho(alpha_each_side));
  const double half = static_cast<double>(n) / 2.0;
  return {static_cast<long>(std::floor(half - b)) + 1, static_cast<long>(std::ceil(half + b))};
}

}  // namespace

double median_sequence_boundary(std::size_t n, double alpha_each_side, double rho) {
  validate(alpha_each_side);
  if (!(rho > 0.0)) throw std::invalid_argument("confidence sequence: rho must be positive");
  // Each increment 1{x <= m} - 1/2 lies in [-1/2, 1/2] with mean 0 at the median, so it is
  // sub-Gaussian with variance proxy 1/4 (Hoeffding): the mixture of exp(l S - l^2 V / 2) over
  // l ~ N(0, 1/rho) is a nonnegative supermartingale, and Ville's inequality bounds the chance
  // it ever exceeds 1 / (2 alpha). Each one-sided half-normal mixture is at least as large, so
  // each side alone is crossed with probability at most alpha.
  const double v = static_cast<double>(n) / 4.0;
  const double a = 2.0 * alpha_each_side;
  return std::sqrt((v + rho) * std::log((v + rho) / (rho * a * a)));
}

double sequence_rho(double alpha_each_side, double design_rounds) {
  validate(alpha_each_side);
  const double log_inverse = std::log(1.0 / (2.0 * alpha_each_side));
  return (design_rounds / 4.0) / (2.0 * log_inverse + std::log(1.0 + 2.0 * log_inverse));
}

std::optional<Interval> median_sequence_interval(std::span<const double> values,
                                                 double alpha_each_side) {
  const std::size_t n = values.size();
  const Ranks ranks = sequence_ranks(n, alpha_each_side);
  if (ranks.lo < 1 || ranks.hi > static_cast<long>(n)) return std::nullopt;
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  return Interval{sorted[static_cast<std::size_t>(ranks.lo - 1)],
                  sorted[static_cast<std::size_t>(ranks.hi - 1)]};
}

std::size_t min_values_for_median_sequence(double alpha_each_side) {
  validate(alpha_each_side);
  // The boundary grows like sqrt(n log n) and n/2 linearly, so a finite interval appears; the
  // cap only guards against a caller's absurd alpha (1e-300 needs about 2,800 values).
  for (std::size_t n = 1; n < 1000000; ++n) {
    const Ranks ranks = sequence_ranks(n, alpha_each_side);
    if (ranks.lo >= 1 && ranks.hi <= static_cast<long>(n)) return n;
  }
  throw std::invalid_argument("confidence sequence: alpha too small for any finite interval");
}

}  // namespace raygate

// What the interval constructions (order statistics, confidence sequences, the bootstrap, a
// family's split, the noisy-image test) share below their formulas: the check that a level lies
// strictly inside its range, the logarithm of a binomial coefficient for the sign test's tails,
// and the standard normal's quantile.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <string_view>

#include <fmt/core.h>

namespace raygate {

// Throws std::invalid_argument("<what> must lie in (low, high)") unless low < value < high
// (a NaN is outside): a level at either end makes an interval empty or the whole line.
inline void require_open_interval(double value, double low, double high, std::string_view what) {
  if (!(value > low && value < high)) {
    throw std::invalid_argument(fmt::format("{} must lie in ({}, {})", what, low, high));
  }
}

// ln C(n, k) for k <= n, through lgamma so that large n neither overflows nor loses digits.
inline double log_choose(std::size_t n, std::size_t k) {
  const auto total = static_cast<double>(n);
  const auto chosen = static_cast<double>(k);
  return std::lgamma(total + 1.0) - std::lgamma(chosen + 1.0) - std::lgamma(total - chosen + 1.0);
}

// The standard normal's quantile: the x with P(Z <= x) = p; -inf at p <= 0, +inf at p >= 1.
// Bisection on the CDF to the last bit (about 60 halvings of [-40, 40]): slower than a rational
// approximation, but exact, and no caller needs more than a few thousand a second.
inline double normal_quantile(double p) {
  if (!(p > 0.0)) return -std::numeric_limits<double>::infinity();
  if (!(p < 1.0)) return std::numeric_limits<double>::infinity();
  double low = -40.0;
  double high = 40.0;
  for (int i = 0; i < 200 && high - low > 1e-13; ++i) {
    const double middle = (low + high) / 2.0;
    (0.5 * std::erfc(-middle / std::sqrt(2.0)) < p ? low : high) = middle;
  }
  return (low + high) / 2.0;
}

}  // namespace raygate

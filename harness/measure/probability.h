// What the interval constructions (order statistics, confidence sequences, the bootstrap, a
// family's split) share below their formulas: the check that a level lies strictly inside its
// range, and the logarithm of a binomial coefficient for the sign test's tails.
#pragma once

#include <cmath>
#include <cstddef>
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

}  // namespace raygate

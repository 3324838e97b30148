#include "measure/median_interval.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "measure/probability.h"

namespace raygate {
namespace {

void validate(double confidence) {
  require_open_interval(confidence, 0.0, 1.0, "median interval: confidence");
}

// P(Binomial(n, 1/2) <= m), summed in logs so large n does not overflow.
double binomial_half_cdf(std::size_t n, std::size_t m) {
  double sum = 0.0;
  const double log_half_n = static_cast<double>(n) * std::log(0.5);
  for (std::size_t i = 0; i <= m && i <= n; ++i) {
    sum += std::exp(log_choose(n, i) + log_half_n);
  }
  return sum;
}

// The largest k >= 1 with 2 P(B < k) <= 1 - confidence, i.e. [x(k), x(n-k+1)] covers with at
// least `confidence`; 0 when even k = 1 (the whole range) does not.
std::size_t order_statistic_rank(std::size_t n, double confidence) {
  const double tail = (1.0 - confidence) / 2.0;
  std::size_t k = 0;
  // Rounding: a tail equal to the allowance (within 1e-12) counts as inside it.
  while (k + 1 <= (n + 1) / 2 && binomial_half_cdf(n, k) <= tail + 1e-12) ++k;
  return k;
}

}  // namespace

std::size_t min_values_for_median_interval(double confidence) {
  validate(confidence);
  std::size_t n = 1;
  while (order_statistic_rank(n, confidence) == 0) ++n;
  return n;
}

std::optional<Interval> median_interval(std::span<const double> values, double confidence) {
  validate(confidence);
  const std::size_t n = values.size();
  const std::size_t k = order_statistic_rank(n, confidence);
  if (k == 0) return std::nullopt;
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  return Interval{sorted[k - 1], sorted[n - k]};
}

}  // namespace raygate

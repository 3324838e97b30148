#include "measure/mann_whitney.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace raygate {
namespace {

struct RankSums {
  double rank_sum_a = 0.0;
  double tie_term = 0.0;  // sum over tie groups of t^3 - t
};

// Midranks (1-based) of the pooled sample, summed over the values that came from `a`.
RankSums rank_pooled(std::span<const double> a, std::span<const double> b) {
  std::vector<std::pair<double, bool>> pooled;  // (value, from a)
  pooled.reserve(a.size() + b.size());
  for (double x : a) pooled.emplace_back(x, true);
  for (double x : b) pooled.emplace_back(x, false);
  std::sort(pooled.begin(), pooled.end(),
            [](const auto& l, const auto& r) { return l.first < r.first; });
  RankSums sums;
  std::size_t start = 0;
  while (start < pooled.size()) {
    std::size_t end = start + 1;
    while (end < pooled.size() && pooled[end].first == pooled[start].first) ++end;
    const double tied = static_cast<double>(end - start);
    const double midrank = (static_cast<double>(start + 1) + static_cast<double>(end)) / 2.0;
    for (std::size_t i = start; i < end; ++i) {
      if (pooled[i].second) sums.rank_sum_a += midrank;
    }
    sums.tie_term += tied * tied * tied - tied;
    start = end;
  }
  return sums;
}

}  // namespace

MannWhitneyResult mann_whitney_u(std::span<const double> a, std::span<const double> b) {
  if (a.empty() || b.empty()) throw std::invalid_argument("mann_whitney_u: empty sample");
  const auto n_a = static_cast<double>(a.size());
  const auto n_b = static_cast<double>(b.size());
  const double n = n_a + n_b;
  const RankSums sums = rank_pooled(a, b);

  MannWhitneyResult result;
  result.u = sums.rank_sum_a - n_a * (n_a + 1.0) / 2.0;
  const double expected_u = n_a * n_b / 2.0;
  const double variance = n_a * n_b / 12.0 * ((n + 1.0) - sums.tie_term / (n * (n - 1.0)));
  if (!(variance > 0.0)) return result;  // every value tied: no evidence either way

  const double deviation = result.u - expected_u;
  // U moves in steps of 1/2, so |deviation| - 1/2 is never negative unless deviation is 0.
  const double corrected = std::max(0.0, std::fabs(deviation) - 0.5);
  result.z = std::copysign(corrected / std::sqrt(variance), deviation);
  result.p_value = std::min(1.0, std::erfc(corrected / std::sqrt(variance) / std::sqrt(2.0)));
  return result;
}

}  // namespace raygate

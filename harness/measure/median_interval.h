// A distribution-free confidence interval for a median, from order statistics: the interval
// [x(k), x(n-k+1)] of the sorted sample covers the true median with probability
// 1 - 2 P(Binomial(n, 1/2) < k), whatever the distribution (continuous). The change verdict uses
// it because a gate decides on few rounds, where the bootstrap's coverage falls far below its
// nominal level (docs/statistics.md §5): with 3 rounds a "95%" interval is [min, max], 75%.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "measure/bootstrap.h"

namespace raygate {

// The fewest values for which some [x(k), x(n-k+1)] reaches `confidence` (6 for 0.95, 8 for
// 0.99): below it no interval from the sample is wide enough, and no verdict may be drawn.
std::size_t min_values_for_median_interval(double confidence);

// The narrowest order-statistic interval whose coverage is at least `confidence`, or nullopt
// when there are fewer values than min_values_for_median_interval(confidence). Throws
// std::invalid_argument for a confidence outside (0, 1).
std::optional<Interval> median_interval(std::span<const double> values, double confidence);

}  // namespace raygate

// An anytime-valid confidence sequence for the median of a stream of values: intervals that
// contain the true median at every round simultaneously with probability 1 - 2 alpha (each end
// is wrong with probability at most alpha), so a compare may look after every round and stop at
// the first decided verdict without inflating its error (docs/statistics.md §6a). Only ranks
// enter, so spikes of any size cost one sign. The construction is a mixture martingale of the
// sign process (Howard & Ramdas' sequential quantile confidence sequences): at the true median
// each 1{x <= m} is a fair coin, so the likelihood ratio of "P(x <= m) = p" against "= 1/2",
// mixed over p uniform on one side of 1/2, is a martingale, and Ville's inequality bounds the
// chance it ever reaches 1 / alpha.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "measure/bootstrap.h"

namespace raygate {

// ln of the one-sided mixture martingale after n values of which `count` fell on the tested
// side (e.g. count = #{x_i <= m} when testing whether m lies above the median):
//   M = 2^n * 2 * integral over p in (1/2, 1) of p^count (1 - p)^(n - count) dp
//     = 2^(n+1) * B(count + 1, n - count + 1) * P(Binomial(n + 1, 1/2) <= count).
// Increasing in count. Throws std::invalid_argument for count > n.
double median_sequence_log_wealth(std::size_t n, std::size_t count);

// The interval at this round, [x(lo), x(hi)] of the sorted values: every m that neither side's
// martingale has rejected at this round, with k* the smallest count whose wealth reaches
// 1 / alpha_each_side, hi = k* and lo = n + 1 - k*. nullopt while it is unbounded (k* > n: too
// few values for any finite interval at this level). Throws std::invalid_argument for alpha
// outside (0, 0.5). Values in measurement order.
std::optional<Interval> median_sequence_interval(std::span<const double> values,
                                                 double alpha_each_side);

// k*: the rank of the interval's upper end among n sorted values (the lower end's is
// n + 1 - k*), or n + 1 while the interval is unbounded. What the interval of n values will be,
// whatever the values: the estimate of the rounds a scene needs projects with it.
std::size_t median_sequence_upper_rank(std::size_t n, double alpha_each_side);

// The fewest values for which the interval can be finite: all n values on one side must reach
// 1 / alpha (8 at alpha 0.025, 14 at 0.01/13).
std::size_t min_values_for_median_sequence(double alpha_each_side);

}  // namespace raygate

// An anytime-valid confidence sequence for the median of a stream of values: intervals that
// contain the true median at every round simultaneously with probability 1 - 2 alpha, so a
// compare may look after every round and stop at the first decided verdict without inflating
// its error (docs/statistics.md §6). The construction is the sign process of Howard & Ramdas'
// sequential quantile confidence sequences with a normal-mixture boundary (Robbins; Howard,
// Ramdas, McAuliffe & Sekhon 2021); only ranks enter, so spikes of any size cost one sign.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "measure/bootstrap.h"

namespace raygate {

// The round count the boundary is tuned for: it is tightest near here and valid everywhere.
inline constexpr double kSequenceDesignRounds = 24.0;

// A normal-mixture boundary on |S_n|, S_n = sum over i <= n of (1{x_i <= m} - 1/2) for the true
// median m, with each side crossed at any round with probability at most alpha_each_side:
//   b_n = sqrt((V + rho) ln((V + rho) / (rho (2 alpha)^2))),  V = n / 4.
// Throws std::invalid_argument for alpha outside (0, 0.5) or rho <= 0.
double median_sequence_boundary(std::size_t n, double alpha_each_side, double rho);

// The mixture precision rho that makes the boundary tightest at V = design_rounds / 4 (Howard et
// al. 2021, §3.5): rho = V / (2 ln(1/a) + ln(1 + 2 ln(1/a))), a = 2 alpha_each_side.
double sequence_rho(double alpha_each_side, double design_rounds = kSequenceDesignRounds);

// The interval at this round, [x(lo), x(hi)] of the sorted values: every m whose count of
// values <= m lies strictly within n/2 +- b_n. nullopt while it is unbounded on either side
// (too few values for any finite interval at this level). Values in measurement order.
std::optional<Interval> median_sequence_interval(std::span<const double> values,
                                                 double alpha_each_side);

// The fewest values for which the interval can be finite (19 at alpha 0.0004, 13 at 0.025).
std::size_t min_values_for_median_sequence(double alpha_each_side);

}  // namespace raygate

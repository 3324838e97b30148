// Change points in a series of measurements (one history series of normalized ratios, oldest
// first) by E-divisive means (Matteson and James, "A Nonparametric Approach for Multiple Change
// Point Analysis of Multivariate Data", JASA 2014; the method MongoDB's performance CI uses to
// find the commit that changed a benchmark). It needs no model of the noise: a split is a change
// point when the energy distance between the two sides is larger than it is for random orders of
// the same values (a permutation test, seeded so that a CI job gives the same answer each time).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace raygate {

struct EDivisiveOptions {
  std::size_t min_segment = 3;     // points on each side of a change; fewer say too little
  std::size_t permutations = 199;  // the smallest p-value is 1 / (permutations + 1)
  double significance = 0.05;      // a split is a change point when p < significance
  std::uint64_t seed = 1;          // of the permutations: same series, same answer
};

struct ChangePoint {
  std::size_t index = 0;     // the first point after the change
  double statistic = 0.0;    // the split's energy statistic (larger: more different sides)
  double p_value = 1.0;      // of the permutation test within its segment
  double mean_before = 0.0;  // of the points between the previous change point and this one
  double mean_after = 0.0;   // of the points between this change point and the next

  // mean_after / mean_before - 1: +0.10 is 10% slower after the change (for ratios).
  double relative_change() const;
};

// The best split of values[begin, end) and its statistic: the index tau (begin + min_segment <=
// tau <= end - min_segment) that maximizes the statistic of [begin, tau) against [tau, kappa)
// over every kappa (tau + min_segment <= kappa <= end). {0, 0} when the segment is too short.
struct Split {
  std::size_t index = 0;
  double statistic = 0.0;
};
Split best_split(const std::vector<double>& values, std::size_t begin, std::size_t end,
                 std::size_t min_segment);

// Every significant change point, in order of index, found by splitting the series at its most
// significant change point and then each side in turn, until no segment has one. means are of
// the segments the final change points delimit.
std::vector<ChangePoint> e_divisive(const std::vector<double>& values,
                                    const EDivisiveOptions& options = {});

}  // namespace raygate

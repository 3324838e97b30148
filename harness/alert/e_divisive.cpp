#include "alert/e_divisive.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "measure/random.h"

namespace raygate {

namespace {

double pairs(std::size_t k) { return static_cast<double>(k) * static_cast<double>(k - 1) / 2.0; }

// The energy statistic of a split into sides of p and q points whose summed distances are
// `between` (across), `left` and `right` (within each side), with alpha = 1 (plain |x - y|).
// A side of one point has no within-side pairs; its mean distance counts as 0.
double split_statistic(std::size_t p, std::size_t q, double between, double left, double right) {
  const double pq = static_cast<double>(p) * static_cast<double>(q);
  double energy = 2.0 * between / pq;
  if (p >= 2) energy -= left / pairs(p);
  if (q >= 2) energy -= right / pairs(q);
  return pq / static_cast<double>(p + q) * energy;
}

double mean_of(const std::vector<double>& values, std::size_t begin, std::size_t end) {
  return std::accumulate(values.begin() + static_cast<long>(begin),
                         values.begin() + static_cast<long>(end), 0.0) /
         static_cast<double>(end - begin);
}

// p-value of `observed` against the best split of random orders of the segment's values.
double permutation_p_value(const std::vector<double>& values, std::size_t begin, std::size_t end,
                           double observed, const EDivisiveOptions& options, Xoshiro256& random) {
  std::vector<double> shuffled(values.begin() + static_cast<long>(begin),
                               values.begin() + static_cast<long>(end));
  std::size_t as_large = 0;
  for (std::size_t r = 0; r < options.permutations; ++r) {
    for (std::size_t i = shuffled.size() - 1; i > 0; --i) {  // Fisher-Yates
      std::swap(shuffled[i], shuffled[random.uniform_below(i + 1)]);
    }
    if (best_split(shuffled, 0, shuffled.size(), options.min_segment).statistic >= observed) {
      ++as_large;
    }
  }
  return static_cast<double>(as_large + 1) / static_cast<double>(options.permutations + 1);
}

struct Segment {
  std::size_t begin;
  std::size_t end;
};

}  // namespace

double ChangePoint::relative_change() const { return mean_after / mean_before - 1.0; }

Split best_split(const std::vector<double>& values, std::size_t begin, std::size_t end,
                 std::size_t min_segment) {
  const std::size_t least = std::max<std::size_t>(min_segment, 1);
  if (end < begin + 2 * least) return {};
  const auto distance = [&](std::size_t a, std::size_t b) {
    return std::abs(values[a] - values[b]);
  };
  // As Matteson and James: [begin, tau) against [tau, kappa) for every kappa, not only the
  // segment's end, so a change that is undone later (slower for a while, then fixed) still
  // stands out against what follows it. The sums grow one point at a time: O(m^3) for m points.
  Split best;
  double left = 0.0;  // summed distances within [begin, tau)
  for (std::size_t tau = begin + 1; tau + least <= end; ++tau) {
    for (std::size_t l = begin; l + 1 < tau; ++l) left += distance(l, tau - 1);
    if (tau < begin + least) continue;
    double between = 0.0;
    double right = 0.0;
    for (std::size_t kappa = tau; kappa < end; ++kappa) {  // add point kappa to the right side
      for (std::size_t l = begin; l < tau; ++l) between += distance(l, kappa);
      for (std::size_t r = tau; r < kappa; ++r) right += distance(r, kappa);
      if (kappa + 1 - tau < least) continue;
      const double statistic = split_statistic(tau - begin, kappa + 1 - tau, between, left, right);
      if (best.index == 0 || statistic > best.statistic) best = {tau, statistic};
    }
  }
  return best;
}

std::vector<ChangePoint> e_divisive(const std::vector<double>& values,
                                    const EDivisiveOptions& options) {
  Xoshiro256 random(options.seed);
  std::vector<ChangePoint> found;
  std::vector<Segment> pending{{0, values.size()}};
  while (!pending.empty()) {
    const Segment segment = pending.back();
    pending.pop_back();
    const Split split = best_split(values, segment.begin, segment.end, options.min_segment);
    if (split.index == 0 || split.statistic <= 0.0) continue;
    const double p =
        permutation_p_value(values, segment.begin, segment.end, split.statistic, options, random);
    if (p >= options.significance) continue;
    found.push_back({split.index, split.statistic, p, 0.0, 0.0});
    // Right side first onto the stack, so the left is split first: the order the random draws
    // are used in is fixed by the series alone.
    pending.push_back({split.index, segment.end});
    pending.push_back({segment.begin, split.index});
  }
  std::sort(found.begin(), found.end(),
            [](const ChangePoint& a, const ChangePoint& b) { return a.index < b.index; });
  for (std::size_t c = 0; c < found.size(); ++c) {
    const std::size_t before = c == 0 ? 0 : found[c - 1].index;
    const std::size_t after = c + 1 == found.size() ? values.size() : found[c + 1].index;
    found[c].mean_before = mean_of(values, before, found[c].index);
    found[c].mean_after = mean_of(values, found[c].index, after);
  }
  return found;
}

}  // namespace raygate

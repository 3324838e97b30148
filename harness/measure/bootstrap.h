// Percentile bootstrap confidence intervals for a median. Resampling uses raygate's own PRNG
// from a fixed seed, so the same samples give the same interval on every machine and every run:
// a gate that flips between runs of the same data would be worse than useless.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "measure/random.h"

namespace raygate {

// "raygate1" in ASCII. Changing it changes every stored CI in the last digits; do not.
inline constexpr std::uint64_t kBootstrapSeed = 0x7261796761746531ULL;

struct Interval {
  double lower = 0.0;
  double upper = 0.0;

  bool contains(double x) const { return lower <= x && x <= upper; }
  double width() const { return upper - lower; }
};

struct BootstrapOptions {
  int resamples = 2000;      // B
  double confidence = 0.95;  // two-sided level of the interval
  std::uint64_t seed = kBootstrapSeed;
};

// B medians of resamples (n draws with replacement) of `values`, drawn from `rng`. The sample is
// sorted once and each resample is kept as counts per sorted position, so a replicate costs
// O(n) instead of a sort.
std::vector<double> bootstrap_median_replicates(std::span<const double> values, int resamples,
                                                Xoshiro256& rng);

// The (1-c)/2 and (1+c)/2 quantiles (definition 7) of the replicates.
Interval percentile_interval(std::vector<double> replicates, double confidence);

// Percentile bootstrap CI of median(values), with a fresh generator seeded from options.seed.
Interval bootstrap_median_interval(std::span<const double> values,
                                   const BootstrapOptions& options = {});

}  // namespace raygate

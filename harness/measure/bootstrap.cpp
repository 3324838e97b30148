#include "measure/bootstrap.h"

#include <algorithm>
#include <stdexcept>

#include "measure/descriptive.h"
#include "measure/probability.h"

namespace raygate {
namespace {

void validate(const BootstrapOptions& options) {
  if (options.resamples < 1) throw std::invalid_argument("bootstrap: resamples must be >= 1");
  require_open_interval(options.confidence, 0.0, 1.0, "bootstrap: confidence");
}

// The value at 0-based rank `rank` of the resample described by counts over `sorted`.
double value_at_rank(std::span<const double> sorted, const std::vector<std::size_t>& counts,
                     std::size_t rank) {
  std::size_t seen = 0;
  for (std::size_t i = 0; i < counts.size(); ++i) {
    seen += counts[i];
    if (seen > rank) return sorted[i];
  }
  return sorted.back();  // unreachable: the counts add up to n > rank
}

double resample_median(std::span<const double> sorted, std::vector<std::size_t>& counts,
                       Xoshiro256& rng) {
  const std::size_t n = sorted.size();
  std::fill(counts.begin(), counts.end(), 0);
  for (std::size_t draw = 0; draw < n; ++draw) ++counts[rng.uniform_below(n)];
  if (n % 2 == 1) return value_at_rank(sorted, counts, n / 2);
  const double low = value_at_rank(sorted, counts, n / 2 - 1);
  const double high = value_at_rank(sorted, counts, n / 2);
  return low + (high - low) / 2.0;  // same midpoint formula as median_of_sorted
}

}  // namespace

std::vector<double> bootstrap_median_replicates(std::span<const double> values, int resamples,
                                                Xoshiro256& rng) {
  if (values.empty()) throw std::invalid_argument("bootstrap: empty sample");
  if (resamples < 1) throw std::invalid_argument("bootstrap: resamples must be >= 1");
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  std::vector<std::size_t> counts(sorted.size());
  std::vector<double> replicates;
  replicates.reserve(static_cast<std::size_t>(resamples));
  for (int b = 0; b < resamples; ++b) replicates.push_back(resample_median(sorted, counts, rng));
  return replicates;
}

Interval percentile_interval(std::vector<double> replicates, double confidence) {
  require_open_interval(confidence, 0.0, 1.0, "bootstrap: confidence");
  std::sort(replicates.begin(), replicates.end());
  const double tail = (1.0 - confidence) / 2.0;
  return {quantile_of_sorted(replicates, tail), quantile_of_sorted(replicates, 1.0 - tail)};
}

Interval bootstrap_median_interval(std::span<const double> values,
                                   const BootstrapOptions& options) {
  validate(options);
  Xoshiro256 rng(options.seed);
  return percentile_interval(bootstrap_median_replicates(values, options.resamples, rng),
                             options.confidence);
}

}  // namespace raygate

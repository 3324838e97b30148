#include "measure/memory_change.h"

#include <algorithm>
#include <vector>

namespace raygate {
namespace {

double median_of(std::span<const long> values) {
  std::vector<long> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  if (n % 2 == 1) return static_cast<double>(sorted[n / 2]);
  return 0.5 * (static_cast<double>(sorted[n / 2 - 1]) + static_cast<double>(sorted[n / 2]));
}

double spread_of(std::span<const long> values) {
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  return static_cast<double>(*hi - *lo);
}

}  // namespace

std::optional<MemorySummary> summarize_memory(std::span<const long> base_kib,
                                              std::span<const long> head_kib) {
  if (base_kib.empty() || head_kib.empty()) return std::nullopt;
  MemorySummary s;
  s.base_runs = base_kib.size();
  s.head_runs = head_kib.size();
  s.base_kib = median_of(base_kib);
  s.head_kib = median_of(head_kib);
  if (s.base_kib <= 0.0) return std::nullopt;  // no peak recorded: nothing to judge
  s.delta_kib = s.head_kib - s.base_kib;
  s.change = s.delta_kib / s.base_kib;
  s.floor_kib = std::max(kMemoryNoiseFloorKib, kMemoryNoiseFraction * s.base_kib);
  s.spread_kib = std::max(spread_of(base_kib), spread_of(head_kib));
  return s;
}

ChangeVerdict classify_memory(const MemorySummary& summary, double max_increase) {
  const double limit = max_increase * summary.base_kib;
  const double delta = summary.delta_kib;
  const double noise = summary.noise_kib();
  if (delta > limit && delta > noise) return ChangeVerdict::regressed;
  if (delta < -limit && delta < -noise) return ChangeVerdict::improved;
  const double size = delta < 0.0 ? -delta : delta;
  if (size <= summary.floor_kib) return ChangeVerdict::unchanged;
  if (size <= limit && summary.spread_kib <= limit) return ChangeVerdict::unchanged;
  return ChangeVerdict::inconclusive;
}

}  // namespace raygate

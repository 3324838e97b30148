// Peak resident memory of head against base (issue 27), and its verdict. Peak RSS of a
// deterministic program repeats to a few pages from run to run, so the rule needs no confidence
// sequence: the median of each side over its rounds, and a noise band that covers page-level
// jitter (docs/gate.md, "Memory"). Memory is judged raw, not divided by the baseline's: the
// baseline normalizes time across machines, and a tracer's peak memory does not depend on the
// machine's speed.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "measure/change.h"

namespace raygate {

inline constexpr double kDefaultMaxMemoryIncrease = 0.10;
// The noise band's floor: allocator arenas and page-table pages move a peak by a few hundred
// KiB between identical runs; 2% at larger sizes.
inline constexpr double kMemoryNoiseFloorKib = 1024.0;
inline constexpr double kMemoryNoiseFraction = 0.02;

struct MemorySummary {
  std::size_t base_runs = 0;
  std::size_t head_runs = 0;
  double base_kib = 0.0;  // median peak over base's runs
  double head_kib = 0.0;
  double delta_kib = 0.0;   // head - base
  double change = 0.0;      // delta / base: +0.10 = 10% more memory
  double floor_kib = 0.0;   // max(1 MiB, 2% of base): changes this small are never judged
  double spread_kib = 0.0;  // the wider of the two sides' spreads (max - min over their runs)

  // What a repeat of the same programs could move delta by: the floor or the spread.
  double noise_kib() const { return floor_kib > spread_kib ? floor_kib : spread_kib; }
};

// nullopt when either side has no peak.
std::optional<MemorySummary> summarize_memory(std::span<const long> base_kib,
                                              std::span<const long> head_kib);

// With limit = max_increase x base: REGRESSED when delta exceeds both the limit and the noise;
// IMPROVED mirrors it; UNCHANGED when |delta| is within the floor, or within the limit while
// neither side spread wider than the limit (a change of the limit's size would have shown);
// otherwise INCONCLUSIVE (the peaks vary as much as the change to be judged).
ChangeVerdict classify_memory(const MemorySummary& summary,
                              double max_increase = kDefaultMaxMemoryIncrease);

}  // namespace raygate

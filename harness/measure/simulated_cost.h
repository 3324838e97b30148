// The cost model of `--timing sim` (docs/simulated-timing.md): a run's cachegrind counters (the
// instructions it executed and its simulated L1 and last-level cache misses) reduced to one
// number, estimated cycles, that stands in for seconds in every ratio. Counting instead of timing
// makes a ratio deterministic; this module also decides whether repeated runs really agreed and,
// when they did, gives the exact change between two revisions (no confidence interval needed).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "measure/change.h"

namespace raygate {

// Cachegrind's totals for one run (every process of it summed), by cachegrind's event names:
// I = instruction fetches, D = data reads (r) and writes (w); 1 = the L1 caches, L = last level.
struct SimulatedCounters {
  std::uint64_t ir = 0, i1mr = 0, ilmr = 0;
  std::uint64_t dr = 0, d1mr = 0, dlmr = 0;
  std::uint64_t dw = 0, d1mw = 0, dlmw = 0;
  int processes = 0;  // how many cachegrind output files (processes) were summed

  SimulatedCounters& operator+=(const SimulatedCounters& other);
  bool operator==(const SimulatedCounters&) const = default;
};

// The weights of the model: an instruction costs one cycle, a miss in L1 that hits the last level
// ten more, a last-level miss (main memory) a hundred more. The same weighting KCachegrind's
// "Cycle Estimation" uses; approximate latencies of a current x86 core, chosen so instruction
// count dominates and only scenes that miss the cache a lot move away from it.
inline constexpr double kL1MissCycles = 10.0;
inline constexpr double kLastLevelMissCycles = 100.0;

// Ir + 10 * (I1mr + D1mr + D1mw) + 100 * (ILmr + DLmr + DLmw).
double estimated_cycles(const SimulatedCounters& counters);

void to_json(nlohmann::json& json, const SimulatedCounters& counters);
void from_json(const nlohmann::json& json, SimulatedCounters& counters);

// The largest relative difference between the estimated cycles of a contender's runs in these
// rounds ((max - min) / min), the spread to report when runs disagree; 0 when all are equal.
double relative_spread(std::span<const double> costs);

// The counted change of head against base when each contender's costs repeated (at least two
// rounds: one run proves nothing): exactly, cost(head) / cost(base) - 1 with a point interval;
// within kCountedSpreadTolerance (measure/counted_spread.h), bounded by the runs' extremes. nullopt
// when they differ more; the caller then uses the statistics of timed rounds (simulated-timing.md).
std::optional<ChangeSummary> exact_change(std::span<const CompareRound> rounds);

// The change of a compare scene: exact when `counted` (sim mode) and every run repeated its
// count, else the statistics of timed rounds (on confidence sequences at `sequence`, if given).
ChangeSummary measured_change(std::span<const CompareRound> rounds, const BootstrapOptions& options,
                              bool counted,
                              const std::optional<SequenceLevels>& sequence = std::nullopt);

// The same question for `run`: true when tracer and baseline each had identical costs in at least
// two rounds.
bool costs_identical(std::span<const RoundSample> rounds);

}  // namespace raygate

// Whether a scene would decide sooner with each side's fastest of two runs per round than with
// one run, judged from the one-run rounds it already has (docs/statistics.md §6d). On a VM a run
// is only ever slowed by what else the host does, so the noise is one-sided and the fastest of
// two is steadier than one: in the identity compares of 2026-11-26, pairing adjacent rounds cut
// the per-round spread of the scenes still undecided from 4-5% to about 1% (jacks 4.25% ->
// 1.24%, nurbtst 5.09% -> 1.00%), worth far more than the rounds' double cost. On a quiet
// machine or a fast tracer it often is not. The compare's second pass asks, scene by scene.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "measure/change.h"
#include "measure/ratio.h"

namespace raygate {

// Fewer pairs than this give no spread: the quartiles of four values say too little.
inline constexpr std::size_t kMinPairsForSpread = 5;

// The fastest of two pays only when it is estimated to need at most this share of one run's
// seconds: its spread comes from a handful of pairs, and a switch that merely breaks even is not
// worth making on that evidence.
inline constexpr double kFastestOfTwoMustSave = 0.75;

// The spread a projection of a sequence's ends should use for these log-changes: the wider of
// the two quartiles' distances from the median, as a normal's sigma (/ 0.6745). For symmetric
// rounds it is about the scaled MAD. One-sided noise is not symmetric: when a third of the runs
// are slowed, the MAD sees only the steady two thirds, while the sequence's upper end, a rank
// near the upper quartile, sits among the slowed ones. Needs at least one value.
double quartile_spread(std::span<const double> log_changes);

// The spread (quartile_spread) the per-round log-changes would have had with each side's
// fastest of two runs: one-run rounds 2k and 2k+1 (adjacent, on the same CPU, in opposite
// orders) make one value ln(min(head) / min(base)), as a round of `--repeats 2` would. nullopt
// below kMinPairsForSpread pairs. Rounds in measurement order; a round's times must be positive.
std::optional<double> fastest_of_two_spread(std::span<const CompareRound> one_run_rounds);

// The same for `run`'s normalized ratio: pairs of one-run rounds make ln(min(tracer) /
// min(baseline)).
std::optional<double> fastest_of_two_spread(std::span<const RoundSample> one_run_rounds);

// For a precision that grows with the rounds (`run`'s interval of the median): is a round of the
// fastest of two, at twice one run's seconds, worth it? Rounds needed go as the spread squared,
// so it pays when 2 * fastest_of_two_spread^2 < kFastestOfTwoMustSave * one_run_spread^2.
bool fastest_of_two_pays(double one_run_spread, double fastest_of_two_spread);

}  // namespace raygate

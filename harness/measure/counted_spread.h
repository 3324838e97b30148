// How far apart the simulated counts of one contender may be and still be counted (--timing
// sim, docs/simulated-timing.md). A deterministic program repeats its cachegrind totals exactly;
// one with a polling thread or clock reads (Debian's POV-Ray) repeats them to a few hundredths
// of a percent, which timed statistics would need six rounds or more to wade through. Within
// this tolerance a change is bounded by the runs' extremes instead, after two rounds.
#pragma once

namespace raygate {

// 0.25%: above every spread measured on POV-Ray (0.001-0.18% in 31 scenes' pairs of runs,
// 2026-11-29) and a quarter of sim mode's default 1% limit. Counted changes are bounded on the
// assumption that no two runs of a contender differ by more, which every pair of runs checks.
inline constexpr double kCountedSpreadTolerance = 0.0025;

// Whether runs whose costs differ by `spread` ((max - min) / min) are counted, not timed.
inline bool counts_agree(double spread) { return spread <= kCountedSpreadTolerance; }

}  // namespace raygate

// The normalized ratio a compare stores for base and head, the number history and `alert` trend
// (docs/statistics.md §6e): how precise it must be, and the rule of the rounds that make it so.
// The change of head against base needs no baseline (it cancels within a round), so while a
// scene's change is being decided the baseline joins only its first --baseline-rounds rounds.
// Once every scene has had its time (after the second pass), the scenes whose stored ratio is
// not yet within +-2% get ratio rounds: rounds as before, baseline, base and head interleaved
// and rotated, the baseline in every one, while the budget has room (pipeline/compare_plan.h).
// They never change a decided verdict: the change stays judged on the rounds it was decided on.
#pragma once

#include <cstddef>
#include <map>
#include <string>

#include "gate/policy.h"
#include "measure/ratio.h"
#include "measure/stopping_policy.h"
#include "results/results.h"
#include "runner/scheduler.h"

namespace raygate {

// The stored ratio is precise once its CI is within +-2% of it...
inline constexpr double kStoredRatioHalfWidth = 0.02;

// ...and ratio rounds stop once the baseline has joined this many of the scene's rounds: at 12
// the 95% interval is the 3rd to the 10th of the sorted log-ratios, and a ratio that noisy is
// said to be, not chased round after round.
inline constexpr std::size_t kStoredRatioMaxRounds = 12;

// The confidence of a scene's stored ratio interval: the scene's 1 - significance (95% by
// default), as every ratio a compare reports.
double stored_ratio_confidence(const GatePolicy& policy, const std::string& scene_id);

// Is `ratio` (at `confidence`) within kStoredRatioHalfWidth, on enough baseline rounds for its
// interval to be one at that confidence (6 at 95%: below that it is the rounds' range, which
// three rounds make a 75% interval)?
bool stored_ratio_precise(const RatioSummary& ratio, double confidence);

// The fewest baseline rounds a precise stored ratio has at `confidence` (6 at 95%).
std::size_t stored_ratio_fewest_rounds(double confidence);

// About how many baseline rounds would make `ratio` precise at `confidence`, projected from its
// rounds' spread (log_ratio_mad_scaled, sigma): the median's interval is about
// z * 1.2533 * sigma / sqrt(n) either side, so n = (z * 1.2533 * sigma / 0.02)^2, and never fewer
// than stored_ratio_fewest_rounds. Ratio rounds are spent only where this is at most
// kStoredRatioMaxRounds: on a runner whose rounds differ by 5%, a ratio within +-2% would take
// about 60 baseline rounds, and a compare is no place to spend them.
std::size_t stored_ratio_rounds_needed(const RatioSummary& ratio, double confidence);

// How many more rounds the scene's ratio rounds may take before the baseline has joined
// kStoredRatioMaxRounds of its rounds.
std::size_t stored_ratio_rounds_left(const SceneResult& scene);

// The stop rule of a scene's ratio rounds: base's ratio against the baseline over every round
// the baseline joined is precise, or `policy`'s budget is spent.
StopRule stored_ratio_stop_rule(const StoppingPolicy& policy, double confidence);

// The compare's closing line on its stored ratios: on how many scenes they are within +-2% and
// from how many baseline rounds, and each scene where they are not, with its interval and why
// (`why_by_scene`, by scene id). Empty for no measured scene.
std::string stored_ratio_line(const ResultsDocument& document, const GatePolicy& policy,
                              const std::map<std::string, std::string>& why_by_scene);

}  // namespace raygate

#include "gate/runner_noise.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/format.h"
#include "measure/change.h"
#include "measure/descriptive.h"

namespace raygate {

std::optional<std::string> runner_noise_note(const ResultsDocument& document,
                                             const GatePolicy& policy) {
  std::vector<double> spreads;
  std::vector<double> rounds;
  std::vector<double> thresholds;
  const ChangeSummary* undecided = nullptr;
  for (const SceneResult& scene : document.scenes) {
    const std::optional<ChangeSummary>& c = scene.change;
    if (!c || c->exact || c->rounds == 0 ||
        c->interval_kind != ChangeIntervalKind::confidence_sequence) {
      continue;
    }
    const double threshold = policy.for_scene(scene.entry.id).max_slowdown;
    spreads.push_back(c->log_change_mad_scaled);
    rounds.push_back(static_cast<double>(c->rounds));
    thresholds.push_back(threshold);
    // Judged as the gate judges it (verdict.cpp judge_speed), from the stored intervals.
    if (classify_change(*c, threshold) == ChangeVerdict::inconclusive) undecided = &*c;
  }
  if (!undecided) return std::nullopt;
  std::string note = fmt::format(
      "runner noise: the rounds of a scene differed by {:.1f}% (head/base per round, scaled MAD, "
      "median of {})",
      100 * median(spreads), count_text(spreads.size(), "scene"));
  const auto typical_rounds = static_cast<std::size_t>(std::lround(median(rounds)));
  const bool one_limit = std::all_of(thresholds.begin(), thresholds.end(),
                                     [&](double t) { return t == thresholds.front(); });
  const std::optional<double> decides_below =
      one_limit ? largest_deciding_spread(typical_rounds, thresholds.front(),
                                          undecided->equivalence_confidence)
                : std::nullopt;
  if (decides_below) {
    note += fmt::format(
        "; in the {} rounds a scene typically got, an unchanged scene is shown within the "
        "{:.1f}% limit (UNCHANGED) only when its rounds differ by less than about {:.1f}%",
        typical_rounds, 100 * thresholds.front(), 100 * *decides_below);
  }
  // Not "--repeats 2": compare already gives the fastest of two to the scenes it pays for, and
  // repeating every round doubles the floor every scene pays (docs/statistics.md §6d).
  return note +
         ". A quieter runner or a longer --max-minutes decides more; raygate doctor "
         "measures a runner's noise.";
}

}  // namespace raygate

#include "pipeline/compare_family.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "measure/confidence_sequence.h"
#include "measure/family.h"
#include "pipeline/stopping.h"

namespace raygate {

namespace {

// A scene whose change the family judges: measured, with rounds, and not exact.
bool in_family(const SceneResult& scene) {
  return scene.change && !scene.change->exact && !scene.runs.rounds.empty();
}

// "balls +0.4% [-3.9%, +4.8%] (width 8.7 points) after 38 rounds", or, below the rounds its
// sequence needs, "balls +0.4% after 9 rounds, no interval yet (needs 16 rounds)": the stored
// interval is then only the observed range.
std::string undecided_scene(const SceneResult& scene) {
  const ChangeSummary& c = *scene.change;
  const std::size_t needed = c.interval_kind == ChangeIntervalKind::confidence_sequence
                                 ? min_values_for_median_sequence((1.0 - c.confidence) / 2.0)
                                 : 0;
  if (c.rounds < needed) {
    return fmt::format("{} {:+.1f}% after {} rounds, no interval yet (needs {} rounds)",
                       scene.entry.id, 100 * c.change, c.rounds, needed);
  }
  return fmt::format("{} {:+.1f}% [{:+.1f}%, {:+.1f}%] (width {:.1f} points) after {} rounds",
                     scene.entry.id, 100 * c.change, 100 * c.change_interval.lower,
                     100 * c.change_interval.upper,
                     100 * (c.change_interval.upper - c.change_interval.lower), c.rounds);
}

}  // namespace

double scene_decision_alpha(const GatePolicy& policy, std::size_t family_size) {
  return scene_sequence_alpha(policy.family_significance, std::max<std::size_t>(family_size, 1));
}

std::vector<double> log_changes(const std::vector<Round>& rounds) {
  std::vector<double> logs;
  logs.reserve(rounds.size());
  for (const CompareRound& r : compare_samples(rounds)) {
    logs.push_back(std::log(r.head_seconds / r.base_seconds));
  }
  return logs;
}

std::vector<std::string> apply_family_control(ResultsDocument& document, const GatePolicy& policy,
                                              std::size_t family_size) {
  std::vector<SceneResult*> measured;
  std::vector<FamilyScene> family;
  for (SceneResult& scene : document.scenes) {
    if (!in_family(scene)) continue;
    const ScenePolicy& p = policy.for_scene(scene.entry.id);
    measured.push_back(&scene);
    family.push_back({log_changes(scene.runs.rounds), p.max_slowdown, p.significance});
  }
  // Holm needs every scene's p-value; a shard (or a compare cut short) has only some, so it
  // keeps the Bonferroni shares, which are valid on their own (`raygate merge` does not re-judge).
  if (family.empty() || family_size > family.size()) return {};
  const std::vector<double> alphas = holm_sequence_alphas(family, policy.family_significance);
  const double measured_at = scene_decision_alpha(policy, family_size);
  std::vector<std::string> changed;
  for (std::size_t i = 0; i < measured.size(); ++i) {
    if (alphas[i] <= measured_at) continue;
    SceneResult& scene = *measured[i];
    const ScenePolicy& p = policy.for_scene(scene.entry.id);
    scene.change = summarize_change(compare_samples(scene.runs.rounds), change_bootstrap(p),
                                    scene_levels(p, alphas[i]));
    scene.change_verdict = std::string(to_string(classify_change(*scene.change, p.max_slowdown)));
    changed.push_back(scene.entry.id);
  }
  return changed;
}

std::string undecided_line(const ResultsDocument& document) {
  std::string line;
  for (const SceneResult& scene : document.scenes) {
    if (!scene.change || scene.change_verdict != to_string(ChangeVerdict::inconclusive)) continue;
    line += (line.empty() ? "" : "; ") + undecided_scene(scene);
  }
  return line.empty() ? line : "undecided (INCONCLUSIVE): " + line;
}

}  // namespace raygate

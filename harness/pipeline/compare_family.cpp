#include "pipeline/compare_family.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "core/format.h"
#include "measure/confidence_sequence.h"
#include "measure/family.h"
#include "pipeline/stop_rules.h"
#include "pipeline/visit_plan.h"

namespace raygate {

namespace {

// A scene whose change the family judges: measured, with rounds, and not exact.
bool in_family(const SceneResult& scene) {
  return scene.change && !scene.change->exact && !scene.runs.rounds.empty();
}

double seconds_per_round(const SceneResult& scene) {
  const std::size_t rounds = scene.runs.rounds.size();
  return rounds > 0 ? scene.runs.seconds_spent / static_cast<double>(rounds) : 0.0;
}

// "(about 180 rounds in all would decide it, 3 min more at this scene's pace, or a quieter
// runner)", or why no number of rounds would do.
std::string what_would_decide(const SceneResult& scene, double threshold) {
  const ChangeSummary& c = *scene.change;
  const std::optional<std::size_t> rounds = rounds_to_decide(scene, threshold);
  if (!rounds) {
    return fmt::format(
        "(a change this close to the {:+.1f}% limit takes more rounds than any "
        "budget; a limit below the smallest slowdown that matters decides it)",
        100 * threshold);
  }
  const std::size_t more = *rounds > c.rounds ? *rounds - c.rounds : 0;
  return fmt::format(
      "(about {} rounds in all would decide it, {} more at this scene's pace, or "
      "a quieter runner)",
      *rounds, duration_text(seconds_per_round(scene) * static_cast<double>(more)));
}

// The interval that would decide the scene (measure/change.h deciding_interval): for an estimate
// inside the limit the equivalence sequence UNCHANGED must fit in, else the decision sequence
// REGRESSED or IMPROVED must clear; the reports' tables print the same one.
DecidingInterval deciding_sequence(const ChangeSummary& c, double threshold) {
  return deciding_interval(c, ChangeVerdict::inconclusive, threshold);
}

// "balls +0.4% [-3.9%, +4.8%] 90% CS (width 8.7 points) after 38 rounds (about ...)", with the
// interval that would decide it (see deciding_sequence), or, below the rounds that sequence
// needs, "balls +0.4% after 5 rounds, no 90% CS yet (needs 7 rounds) (about ...)".
std::string undecided_scene(const SceneResult& scene, double threshold) {
  const ChangeSummary& c = *scene.change;
  const DecidingInterval sequence = deciding_sequence(c, threshold);
  if (const std::size_t needed = rounds_to_bound(c, sequence); c.rounds < needed) {
    return fmt::format(
        "{} {:+.1f}% after {}, no {} yet (it needs {} rounds at least, {} "
        "more at this scene's pace)",
        scene.entry.id, 100 * c.change, count_text(c.rounds, "round"), interval_name(sequence),
        needed, duration_text(seconds_per_round(scene) * static_cast<double>(needed - c.rounds)));
  }
  const Interval& i = sequence.interval;
  return fmt::format("{} {:+.1f}% [{:+.1f}%, {:+.1f}%] {} (width {:.1f} points) after {} {}",
                     scene.entry.id, 100 * c.change, 100 * i.lower, 100 * i.upper,
                     interval_name(sequence), 100 * (i.upper - i.lower),
                     count_text(c.rounds, "round"), what_would_decide(scene, threshold));
}

}  // namespace

double scene_decision_alpha(const GatePolicy& policy, std::size_t family_size) {
  return scene_sequence_alpha(policy.family_significance, std::max<std::size_t>(family_size, 1));
}

std::vector<double> log_changes(const std::vector<Round>& rounds) {
  return compare_log_changes(compare_samples(rounds));
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
    scene.change_verdict = classify_change(*scene.change, p.max_slowdown);
    changed.push_back(scene.entry.id);
  }
  return changed;
}

std::string undecided_line(const ResultsDocument& document, const GatePolicy& policy) {
  std::string line;
  for (const SceneResult& scene : document.scenes) {
    if (!scene.change || scene.change_verdict != ChangeVerdict::inconclusive) continue;
    line += (line.empty() ? "" : "; ") +
            undecided_scene(scene, policy.for_scene(scene.entry.id).max_slowdown);
  }
  return line.empty() ? line : "undecided (INCONCLUSIVE): " + line;
}

}  // namespace raygate

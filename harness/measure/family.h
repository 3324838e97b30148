// Family-wise control over the scenes of one compare: with K scenes each judged at its own 1%,
// some scene of an unchanged commit fails far more often than 1% (13 scenes at 2.5%: 28%). Each
// scene's confidence sequence runs at the Bonferroni share family/K while it is measured (so it
// may stop as soon as it is decided), and afterwards Holm's step-down gives the scenes left
// undecided the shares the rejected ones no longer need (docs/statistics.md §7). Exit 1 for
// speed then means: at most `family` chance per compare when nothing changed.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "measure/change.h"

namespace raygate {

// The chance that a compare of an unchanged commit calls any scene REGRESSED.
inline constexpr double kDefaultFamilySignificance = 0.01;

// Each scene's share while it is measured: family / scenes, the alpha of each side of its
// confidence sequence. Throws std::invalid_argument for no scenes or family outside (0, 1).
double scene_sequence_alpha(double family_significance, std::size_t scenes);

struct FamilyScene {
  std::vector<double> log_changes;  // ln(t_head / t_base) per round, in measurement order
  double threshold = 0.03;          // the scene's max slowdown
  double equivalence_alpha = 0.05;  // its UNCHANGED level (ScenePolicy::significance)
};

// The scene's verdict (docs/statistics.md §6) with its decision sequence at `alpha` each side:
// the verdict classify_change gives the summary of those rounds at those levels, without the
// ratios' bootstrap (the stopping rule asks after every round).
ChangeVerdict sequence_verdict(const FamilyScene& scene, double alpha);

// sequence_verdict(scene, alpha) == REGRESSED.
bool regressed_at(const FamilyScene& scene, double alpha);

// Holm's step-down over the scenes' REGRESSED tests, where a scene's p-value is the smallest
// alpha at which it is REGRESSED (the verdict is monotone in alpha: a narrower interval keeps
// every REGRESSED condition). Returns each scene's alpha: family/K for a scene not rejected,
// family/(K - r) for one rejected after r others. Valid at any stopping time of each scene
// because every sequence is anytime-valid.
std::vector<double> holm_sequence_alphas(std::span<const FamilyScene> scenes,
                                         double family_significance);

}  // namespace raygate

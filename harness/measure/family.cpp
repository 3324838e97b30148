#include "measure/family.h"

#include <algorithm>
#include <stdexcept>

#include "measure/probability.h"

namespace raygate {

double scene_sequence_alpha(double family_significance, std::size_t scenes) {
  if (scenes == 0) throw std::invalid_argument("family: no scenes");
  require_open_interval(family_significance, 0.0, 1.0, "family: significance");
  // Each side gets the whole share: only the lower side can raise a false alarm (REGRESSED),
  // so the family's error is the sum of the lower sides' errors.
  return std::min(family_significance / static_cast<double>(scenes), 0.49);
}

ChangeVerdict sequence_verdict(const FamilyScene& scene, double alpha) {
  if (scene.log_changes.empty()) return ChangeVerdict::inconclusive;
  SequenceLevels levels;
  levels.decision_alpha = alpha;
  levels.equivalence_alpha = scene.equivalence_alpha;
  return classify_sequential(sequential_intervals(scene.log_changes, levels), scene.threshold);
}

bool regressed_at(const FamilyScene& scene, double alpha) {
  return sequence_verdict(scene, alpha) == ChangeVerdict::regressed;
}

std::vector<double> holm_sequence_alphas(std::span<const FamilyScene> scenes,
                                         double family_significance) {
  const std::size_t k = scenes.size();
  std::vector<double> alphas(k, k == 0 ? 0.0 : scene_sequence_alpha(family_significance, k));
  std::vector<bool> rejected(k, false);
  std::size_t rejections = 0;
  // Rejecting every scene that passes at family/m at once, then moving to family/(m - r), is
  // Holm's procedure on the sorted p-values: each pass can only add rejections.
  for (bool added = true; added && rejections < k;) {
    added = false;
    const double alpha = scene_sequence_alpha(family_significance, k - rejections);
    std::size_t new_rejections = 0;
    for (std::size_t i = 0; i < k; ++i) {
      if (rejected[i] || !regressed_at(scenes[i], alpha)) continue;
      rejected[i] = true;
      alphas[i] = alpha;
      ++new_rejections;
      added = true;
    }
    rejections += new_rejections;
  }
  return alphas;
}

}  // namespace raygate

#include "pipeline/image_stop.h"

#include <utility>

#include "compare/noisy_image_check.h"
#include "pipeline/run_images.h"

namespace raygate {

std::size_t last_image_look(std::size_t rounds) {
  std::size_t last = 0;
  for (std::size_t look = 2; look <= rounds; look = (3 * look + 1) / 2) last = look;  // ceil(1.5x)
  return last;
}

SceneVerdict noisy_image_verdict(const NoisyImageFamily& family, double tolerance) {
  const NoisyThresholds thresholds = noisy_thresholds_for(family.images, tolerance);
  return [thresholds](const std::vector<Round>& rounds) {
    const std::size_t look = last_image_look(rounds.size());
    if (look == 0) return false;
    SceneRuns so_far;
    so_far.rounds.assign(rounds.begin(), rounds.begin() + static_cast<long>(look));
    const std::vector<std::filesystem::path> head = run_images(so_far, Role::head);
    const std::vector<std::filesystem::path> base = run_images(so_far, Role::base);
    if (head.empty() || base.empty()) return false;
    // No evidence is written while measuring: the check at the end writes it.
    const ImageCheck check =
        check_noisy_images(Role::head, ImageReference::base, head, base, thresholds, {}, {});
    return check.verdict != ImageVerdict::inconclusive;
  };
}

SceneVerdict both_decided(SceneVerdict first, SceneVerdict second) {
  return [first = std::move(first), second = std::move(second)](const std::vector<Round>& rounds) {
    return first(rounds) && second(rounds);
  };
}

StopRule compare_stop_rule(const StoppingPolicy& policy, const ScenePolicy& scene,
                           const SequenceLevels& levels, bool counted,
                           const std::optional<NoisyImageFamily>& images) {
  SceneVerdict speed = change_verdict(policy, scene, levels, counted);
  if (!images) return stop_rule(policy, std::move(speed));
  return stop_rule(
      policy, both_decided(std::move(speed), noisy_image_verdict(*images, scene.image_tolerance)));
}

}  // namespace raygate

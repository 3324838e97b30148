#include "pipeline/image_stop.h"

#include <limits>
#include <utility>

#include "compare/noisy_image_check.h"
#include "pipeline/run_images.h"

namespace raygate {

std::size_t last_image_look(std::size_t rounds) {
  std::size_t last = 0;
  std::size_t looks = 0;
  for (std::size_t look = 2; look <= rounds && looks < kImageLooks; look = (3 * look + 1) / 2) {
    last = look;  // the next is ceil(1.5x)
    ++looks;
  }
  return last;
}

NoisyThresholds image_look_thresholds(std::size_t images_in_family, double tolerance) {
  NoisyThresholds thresholds = noisy_thresholds_for(images_in_family, tolerance);
  thresholds.alpha /= static_cast<double>(kImageLooks);
  thresholds.equivalence_alpha /= static_cast<double>(kImageLooks);
  return thresholds;
}

SceneRuns image_look_runs(const SceneRuns& runs) {
  SceneRuns looked;
  const std::size_t look = last_image_look(runs.rounds.size());
  looked.rounds.assign(runs.rounds.begin(), runs.rounds.begin() + static_cast<long>(look));
  return looked;
}

SceneVerdict noisy_image_verdict(const NoisyImageFamily& family, double tolerance) {
  const NoisyThresholds thresholds = image_look_thresholds(family.images, tolerance);
  const std::size_t final_look = last_image_look(std::numeric_limits<std::size_t>::max());
  return [thresholds, final_look](const std::vector<Round>& rounds) {
    const std::size_t look = last_image_look(rounds.size());
    if (look == 0) return false;
    // Past the last look more runs would not be judged: the image does not keep the scene.
    if (look == final_look && rounds.size() > look) return true;
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

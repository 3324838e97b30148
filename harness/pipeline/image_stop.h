// When a compare of a Monte Carlo tracer may stop measuring a scene: its speed change decided
// is not enough while head's image against base's is inconclusive, since more runs a side
// (each rendered with its own seed) are exactly what decides an image. Such a scene keeps
// measuring rounds while its time share allows, as an undecided speed change does
// (docs/monte-carlo-images.md, "More runs for an undecided image").
#pragma once

#include <cstddef>
#include <optional>

#include "compare/noisy_image_compare.h"
#include "gate/policy.h"
#include "measure/stopping_policy.h"
#include "pipeline/stop_rules.h"
#include "runner/scheduler.h"

namespace raygate {

// The Monte Carlo image check of a compare, as its stop rule asks it.
struct NoisyImageFamily {
  std::size_t images = 1;  // the images the check's false-failure rate is split over
};

// The rounds of the last look at the image after `rounds` rounds (0: none yet). The image is
// looked at after 2, 3, 5, 8, 12, 18, 27, 41 and 62 rounds (each look at least 1.5 times the runs
// of the one before), and no more: kImageLooks looks in all.
inline constexpr std::size_t kImageLooks = 9;
std::size_t last_image_look(std::size_t rounds);

// The check's thresholds at each look. Every look is another chance for a change right at the
// tolerance to pass by luck, or for an unchanged image to fail (looking after every round raised
// a false pass from 5% to 21% by 41 runs, these looks at the full level to 13%:
// docs/monte-carlo-images.md). So each look tests at 1/kImageLooks of the check's rates
// (Bonferroni over the looks): all looks together keep the 5% and the family's 1%.
NoisyThresholds image_look_thresholds(std::size_t images_in_family, double tolerance);

// The runs the image is judged on once measuring ends: those of the rounds up to the last look,
// the runs the stop rule judged (warm-ups and a round cut short left out), so the verdict is one
// of the looks the error rates were shared over.
SceneRuns image_look_runs(const SceneRuns& runs);

// Decided when head's runs against base's in the rounds of the last look are pass or fail
// (compare/noisy_image_check.h, at `tolerance`, at image_look_thresholds()); an image that cannot
// be read counts as decided (it fails whatever more runs show), and so does one past the last
// look (more runs would not be looked at).
SceneVerdict noisy_image_verdict(const NoisyImageFamily& family, double tolerance);

// Both `first` and `second` decided; `second` is asked only once `first` is.
SceneVerdict both_decided(SceneVerdict first, SceneVerdict second);

// compare's rule: change_stop_rule(), and with `images` (a Monte Carlo adapter) the image
// decided as well.
StopRule compare_stop_rule(const StoppingPolicy& policy, const ScenePolicy& scene,
                           const SequenceLevels& levels, bool counted,
                           const std::optional<NoisyImageFamily>& images);

}  // namespace raygate

// When a compare of a Monte Carlo tracer may stop measuring a scene: its speed change decided
// is not enough while head's image against base's is inconclusive, since more runs a side
// (each rendered with its own seed) are exactly what decides an image. Such a scene keeps
// measuring rounds while its time share allows, as an undecided speed change does
// (docs/monte-carlo-images.md, "More runs for an undecided image").
#pragma once

#include <cstddef>
#include <optional>

#include "gate/policy.h"
#include "measure/stopping_policy.h"
#include "pipeline/stop_rules.h"

namespace raygate {

// The Monte Carlo image check of a compare, as its stop rule asks it.
struct NoisyImageFamily {
  std::size_t images = 1;  // the images the check's false-failure rate is split over
};

// The rounds of the last look at the image after `rounds` rounds (0: none yet). The image is
// looked at after 2, 3, 5, 8, 12, 18, 27, 41, ... rounds (each look at least 1.5 times the runs
// of the one before). Every look is another chance for a change right at the tolerance to pass
// by luck; looking after every round would raise that chance from 5% to about 15% by 60 rounds,
// these looks to about 7% (simulated: docs/monte-carlo-images.md).
std::size_t last_image_look(std::size_t rounds);

// Decided when head's runs against base's in the rounds of the last look are pass or fail
// (compare/noisy_image_check.h, at `tolerance`); an image that cannot be read counts as decided
// (it fails whatever more runs show).
SceneVerdict noisy_image_verdict(const NoisyImageFamily& family, double tolerance);

// Both `first` and `second` decided; `second` is asked only once `first` is.
SceneVerdict both_decided(SceneVerdict first, SceneVerdict second);

// compare's rule: change_stop_rule(), and with `images` (a Monte Carlo adapter) the image
// decided as well.
StopRule compare_stop_rule(const StoppingPolicy& policy, const ScenePolicy& scene,
                           const SequenceLevels& levels, bool counted,
                           const std::optional<NoisyImageFamily>& images);

}  // namespace raygate

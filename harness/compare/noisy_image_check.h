// The Monte Carlo image check as an ImageCheck (compare/image_check.h), so results documents,
// the gate and every report show it where they show the per-pixel check: a role's runs (each
// rendered with its own {seed}) against the reference's runs or a golden's statistics. The
// comparison itself goes into ImageCheck::noisy (metrics stay empty); its verdict maps to the
// image verdict of the same name.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "compare/golden.h"
#include "compare/image_check.h"
#include "compare/noisy_image_compare.h"

namespace raygate {

// The chance that a suite whose images did not change fails any of them, split evenly over the
// images checked (Bonferroni across scenes; Holm within each image). `tolerance`: the image
// tolerance (gate policy `image_tolerance`).
inline constexpr double kNoisyFamilyAlpha = 0.01;
NoisyThresholds noisy_thresholds_for(std::size_t images_in_family,
                                     double tolerance = kDefaultImageTolerance);

ImageVerdict to_image_verdict(NoisyVerdict verdict);

// `actual` against `expected` (both: every successful run's image). An actual image that cannot
// be read or has NaN/Inf pixels fails; an expected one makes the check an error. On fail, writes
// evidence into evidence_dir: <stem>.actual.png and <stem>.expected.png (the runs' means) and
// <stem>.tiles.png (the mean difference x 16, biased tiles outlined red where actual is brighter
// and blue where darker); none with evidence_dir empty.
ImageCheck check_noisy_images(Role role, ImageReference reference,
                              const std::vector<std::filesystem::path>& actual,
                              const std::vector<std::filesystem::path>& expected,
                              const NoisyThresholds& thresholds,
                              const std::filesystem::path& evidence_dir, const std::string& stem);

// Against the golden statistics `noise` (whose mean image is `mean_file`, listed in the manifest
// as `entry`): statistics of another size than the entry lists are an error of the golden, not
// a difference of the tracer's.
ImageCheck check_noisy_against_stats(Role role, const std::vector<std::filesystem::path>& actual,
                                     const std::filesystem::path& mean_file,
                                     const std::filesystem::path& golden_dir,
                                     const GoldenEntry& entry, const GoldenNoise& noise,
                                     const NoisyThresholds& thresholds,
                                     const std::filesystem::path& evidence_dir,
                                     const std::string& stem);

}  // namespace raygate

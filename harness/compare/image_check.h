// One image checked against a reference (a golden, or the base revision's image): the metrics,
// the verdict in idiff's terms, and evidence images when it fails. A tracer's image that cannot
// be read, or has NaN pixels, fails its check; a check that cannot be made (an unreadable or
// broken reference) is a result with verdict error, never an exception, so one broken scene
// does not stop a suite.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "compare/golden.h"
#include "compare/image_compare.h"
#include "compare/image_verdict.h"
#include "compare/noisy_image_compare.h"
#include "core/domain.h"

namespace raygate {

// What an image was checked against: a blessed golden, or (compare) the base revision's image.
enum class ImageReference { golden, base };

std::string_view to_string(ImageReference reference);  // "golden", "base"
std::optional<ImageReference> parse_image_reference(std::string_view word);

struct ImageCheck {
  Role role = Role::tracer;  // whose image: tracer, base or head
  ImageReference reference = ImageReference::golden;
  std::filesystem::path actual;
  std::filesystem::path expected;
  // pass, warn, fail (also: the actual image unreadable or with NaN pixels); inconclusive (a
  // Monte Carlo image too noisy to decide); missing when there is no golden to compare with
  // (noted once per report, never failed); error when the reference could not be read.
  ImageVerdict verdict = ImageVerdict::error;
  // For missing and error: what went wrong and what to do; beside a Monte Carlo comparison, its
  // notes (identical runs, evidence not written).
  std::string error;
  std::optional<ImageMetrics> metrics;          // the per-pixel check's
  std::vector<std::filesystem::path> evidence;  // actual, expected, |diff| x16 on failure
  std::optional<NoisyComparison> noisy;  // the Monte Carlo check's (compare/noisy_image_compare.h)

  bool failed() const { return verdict == ImageVerdict::fail; }
};

// What a check found, in the words every report prints: the per-pixel metrics' summary, the
// Monte Carlo comparison's line (with its notes), or what went wrong.
std::string check_detail(const ImageCheck& check);

// Whose image against what, as logs name a check: "tracer" against a golden, else
// "head<between>base" ("head-vs-base", "head vs base").
std::string check_label(const ImageCheck& check, std::string_view between);

// Compares `actual` with `expected`; on fail writes evidence into evidence_dir as <stem>.*.png.
ImageCheck check_image(Role role, ImageReference reference, const std::filesystem::path& actual,
                       const std::filesystem::path& expected, const ImageThresholds& thresholds,
                       const std::filesystem::path& evidence_dir, const std::string& stem);

// The golden of suite scene `rendered.id` in `golden_dir` (per its manifest), checked as above.
// `rendered` says what `actual` is a picture of (scene, size; width and height unless 0, the
// scene's own; sampling unless empty): a golden made from other settings, such as another
// suite's scene under the same id, is no golden for it. A missing golden, or one of other
// settings, gives verdict missing, saying why; an empty golden set says the same words for
// every scene ("no goldens in DIR"), so a report says it once. The image is still read: one
// that is unreadable, has NaN pixels or is not `rendered`'s width x height (when given) fails
// all the same. An image whose run folder is gone (deleted while raygate ran) is verdict error:
// the check could not be made.
ImageCheck check_against_golden(Role role, const std::filesystem::path& actual,
                                const std::filesystem::path& golden_dir,
                                const GoldenManifest& manifest, const GoldenEntry& rendered,
                                const ImageThresholds& thresholds,
                                const std::filesystem::path& evidence_dir);

// The same for a Monte Carlo tracer (compare/noisy_image_check.h): every run's image of the
// scene against the golden's statistics. A golden blessed from a single image (no "noise" in
// the manifest) cannot judge noisy renders: verdict missing, saying how to bless one.
ImageCheck check_runs_against_golden(Role role, const std::vector<std::filesystem::path>& actual,
                                     const std::filesystem::path& golden_dir,
                                     const GoldenManifest& manifest, const GoldenEntry& rendered,
                                     const NoisyThresholds& thresholds,
                                     const std::filesystem::path& evidence_dir);

}  // namespace raygate

#include "compare/noisy_image_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "compare/image_compare.h"
#include "compare/noisy_image_files.h"
#include "compare/run_folder.h"
#include "core/error.h"

namespace raygate {

namespace {

// Why one of the tracer's own images is unusable (it fails the check), or nothing.
std::optional<std::string> broken_image(const std::filesystem::path& image) {
  if (std::string problem = unreadable_image(image); !problem.empty()) return problem;
  const RgbImage pixels = read_rgb_image(image);
  const auto bad =
      std::find_if(pixels.rgb.begin(), pixels.rgb.end(), [](float v) { return !std::isfinite(v); });
  if (bad == pixels.rgb.end()) return std::nullopt;
  const auto pixel = static_cast<std::size_t>(bad - pixels.rgb.begin()) / 3;
  return image.string() + ": NaN/Inf pixels, first at (" +
         std::to_string(pixel % static_cast<std::size_t>(pixels.width)) + "," +
         std::to_string(pixel / static_cast<std::size_t>(pixels.width)) + ")";
}

// The runs' mean as a picture to look at: gamma 2.2 like a tracer's own 8-bit output (the
// statistics are linear radiance; written as is, mid-tones look almost black).
RgbImage mean_image(const NoisyImageStats& stats) {
  RgbImage image{stats.width, stats.height, stats.mean};
  for (float& v : image.rgb) v = v > 0 ? std::pow(std::min(v, 1.0f), 1 / 2.2f) : 0.0f;
  return image;
}

// |actual - expected| x 16, with each biased tile's border painted: red where actual is
// brighter, blue where darker.
RgbImage tile_map(const NoisyImageStats& actual, const NoisyImageStats& expected,
                  const NoisyComparison& comparison) {
  RgbImage map{actual.width, actual.height, std::vector<float>(actual.mean.size())};
  for (std::size_t i = 0; i < map.rgb.size(); ++i) {
    map.rgb[i] = std::min(1.0f, 16 * std::abs(actual.mean[i] - expected.mean[i]));
  }
  for (const BiasedTile& t : comparison.biased) {
    const float colour[3] = {t.change.change > 0 ? 1.0f : 0.0f, 0.0f,
                             t.change.change > 0 ? 0.0f : 1.0f};
    for (int y = t.rect.y; y < t.rect.y + t.rect.height; ++y) {
      for (int x = t.rect.x; x < t.rect.x + t.rect.width; ++x) {
        const bool border = x == t.rect.x || y == t.rect.y || x == t.rect.x + t.rect.width - 1 ||
                            y == t.rect.y + t.rect.height - 1;
        if (!border) continue;
        for (int c = 0; c < 3; ++c) {
          map.rgb[(static_cast<std::size_t>(y) * map.width + x) * 3 + c] = colour[c];
        }
      }
    }
  }
  return map;
}

void write_noisy_evidence(ImageCheck& check, const NoisyImageStats& actual,
                          const NoisyImageStats& expected, const NoisyComparison& comparison,
                          const std::filesystem::path& dir, const std::string& stem) {
  if (comparison.size_mismatch) return;
  try {
    std::filesystem::create_directories(dir);
    const std::filesystem::path paths[3] = {
        dir / (stem + ".actual.png"), dir / (stem + ".expected.png"), dir / (stem + ".tiles.png")};
    write_rgb_image(mean_image(actual), paths[0]);
    write_rgb_image(mean_image(expected), paths[1]);
    write_rgb_image(tile_map(actual, expected, comparison), paths[2]);
    check.evidence.assign(std::begin(paths), std::end(paths));
  } catch (const Error& e) {
    check.error +=
        std::string(check.error.empty() ? "" : "; ") + "evidence not written: " + e.what();
  }
}

// The tracer's images checked for what fails them whatever the reference; nullopt when usable.
std::optional<ImageCheck> unusable_actual(ImageCheck check,
                                          const std::vector<std::filesystem::path>& actual) {
  if (actual.empty()) {
    check.verdict = ImageVerdict::error;
    check.error = "no successful run, so no image to check";
    return check;
  }
  for (const std::filesystem::path& image : actual) {
    if (std::optional<std::string> gone = vanished_run_folder(image)) {
      check.verdict = ImageVerdict::error;  // could not be checked: exit 3, not a regression
      check.error = std::move(*gone);
      return check;
    }
    if (std::optional<std::string> problem = broken_image(image)) {
      check.verdict = ImageVerdict::fail;
      check.error = std::move(*problem);
      return check;
    }
  }
  return std::nullopt;
}

// Several runs and not one pixel differs: the tracer ignores its seed (or is deterministic), and
// the test's noise estimate is zero.
bool identical_runs(const NoisyImageStats& stats) {
  return stats.runs >= 2 && std::all_of(stats.variance.begin(), stats.variance.end(),
                                        [](float v) { return v == 0.0f; });
}

// The tracer's runs against the reference's statistics; runs of different sizes fail.
ImageCheck judged(ImageCheck check, const std::vector<std::filesystem::path>& actual_images,
                  const NoisyImageStats& expected, const NoisyThresholds& thresholds,
                  const std::filesystem::path& evidence_dir, const std::string& stem) {
  NoisyImageStats actual;
  try {
    actual = stats_of_images(actual_images);
  } catch (const Error& e) {
    // Read a moment ago: a folder deleted since makes the check impossible, not failed.
    const auto gone = std::find_if(actual_images.begin(), actual_images.end(),
                                   [](const auto& image) { return vanished_run_folder(image); });
    check.verdict = gone == actual_images.end() ? ImageVerdict::fail : ImageVerdict::error;
    check.error = e.what();
    return check;
  }
  const NoisyComparison comparison = compare_noisy(actual, expected, thresholds);
  check.verdict = to_image_verdict(comparison.verdict);
  check.noisy = comparison;
  if (identical_runs(actual)) {
    check.error = "note: the " + std::to_string(actual.runs) +
                  " runs' images are identical: is {seed} reaching the tracer's random numbers?";
  }
  if (comparison.verdict == NoisyVerdict::fail && !evidence_dir.empty()) {
    write_noisy_evidence(check, actual, expected, comparison, evidence_dir, stem);
  }
  return check;
}

// The first value of `values` that is not finite, or (`non_negative`) below zero: "(x,y) channel
// value"; nullopt when all are.
std::optional<std::string> first_bad_value(const std::vector<float>& values, int width,
                                           bool non_negative) {
  const auto bad = std::find_if(values.begin(), values.end(), [&](float v) {
    return !std::isfinite(v) || (non_negative && v < 0.0f);
  });
  if (bad == values.end()) return std::nullopt;
  const auto index = static_cast<std::size_t>(bad - values.begin());
  const std::size_t pixel = index / 3;
  return fmt::format("{} at ({},{}) channel {}", *bad, pixel % static_cast<std::size_t>(width),
                     pixel / static_cast<std::size_t>(width), "RGB"[index % 3]);
}

// A golden whose own noise leaves every channel's whole-image mean uncertain by more than the
// mean itself (one standard error) cannot tell its picture from a black one, the largest
// darkening there is: it judges nothing. A sane golden's error is a fraction of a percent; the
// sweep's variance x 1e30 gave +-4e14 %. Names the channel that comes closest to deciding.
std::optional<std::string> undecidable_noise(const NoisyImageStats& golden,
                                             const std::filesystem::path& variance_file) {
  const TileRect whole = tile_grid(golden.width, golden.height, kWholeImage).front();
  int best = -1;
  TileEstimate best_estimate;
  for (int c = 0; c < 3; ++c) {
    const TileEstimate e = estimate_tile(golden, whole, c, kWholeImage);
    if (!(std::sqrt(e.variance_of_mean) > e.mean)) return std::nullopt;  // this channel decides
    if (best < 0 || std::sqrt(e.variance_of_mean) / e.mean <
                        std::sqrt(best_estimate.variance_of_mean) / best_estimate.mean) {
      best = c;
      best_estimate = e;
    }
  }
  return fmt::format(
      "{}: with this variance the golden's whole-image mean of channel {} (its surest) is {:.4g} "
      "+- {:.3g} over {} runs, uncertain by more than itself: it could not tell its picture from "
      "a black one, so no comparison against it could fail; bless it again from more runs",
      variance_file.string(), "RGB"[best], best_estimate.mean,
      std::sqrt(best_estimate.variance_of_mean), golden.runs);
}

// A golden's statistics that could never fail a comparison (a NaN or negative variance makes
// every test's noise NaN or imaginary; one too large to tell the picture from black), or that
// hold no picture (a NaN mean).
std::optional<std::string> nonsense_statistics(const NoisyImageStats& golden,
                                               const std::filesystem::path& mean_file,
                                               const std::filesystem::path& variance_file) {
  if (auto bad = first_bad_value(golden.variance, golden.width, true)) {
    return variance_file.string() + ": a variance must be a finite number >= 0, found " + *bad +
           "; with it the golden could never fail a comparison";
  }
  if (auto bad = first_bad_value(golden.mean, golden.width, false)) {
    return mean_file.string() + ": the golden mean must be finite, found " + *bad;
  }
  return undecidable_noise(golden, variance_file);
}

}  // namespace

NoisyThresholds noisy_thresholds_for(std::size_t images_in_family, double tolerance) {
  NoisyThresholds thresholds;
  thresholds.alpha =
      kNoisyFamilyAlpha / static_cast<double>(std::max<std::size_t>(1, images_in_family));
  thresholds.tolerance = tolerance;
  return thresholds;
}

ImageVerdict to_image_verdict(NoisyVerdict verdict) {
  switch (verdict) {
    case NoisyVerdict::pass: return ImageVerdict::pass;
    case NoisyVerdict::fail: return ImageVerdict::fail;
    case NoisyVerdict::inconclusive: return ImageVerdict::inconclusive;
  }
  return ImageVerdict::inconclusive;
}

ImageCheck check_noisy_images(Role role, ImageReference reference,
                              const std::vector<std::filesystem::path>& actual,
                              const std::vector<std::filesystem::path>& expected,
                              const NoisyThresholds& thresholds,
                              const std::filesystem::path& evidence_dir, const std::string& stem) {
  ImageCheck check{role,
                   reference,
                   actual.empty() ? std::filesystem::path() : actual.front(),
                   expected.empty() ? std::filesystem::path() : expected.front(),
                   ImageVerdict::error,
                   {},
                   std::nullopt,
                   {},
                   std::nullopt};
  if (auto unusable = unusable_actual(check, actual)) return *unusable;
  if (expected.empty()) {
    check.error =
        "the " + std::string(to_string(reference)) + " revision has no image to compare with";
    return check;
  }
  // A reference image with NaN is no reference: the check could not be made, and no
  // comparison of means is printed as if it had been.
  for (const std::filesystem::path& image : expected) {
    if (auto broken = broken_image(image)) {
      check.error = *broken + " (the " + std::string(to_string(reference)) +
                    " revision's image); nothing to compare with";
      return check;
    }
  }
  NoisyImageStats expected_stats;
  try {
    expected_stats = stats_of_images(expected);
  } catch (const Error& e) {
    check.error = e.what();  // the reference's images: the check could not be made
    return check;
  }
  return judged(check, actual, expected_stats, thresholds, evidence_dir, stem);
}

ImageCheck check_noisy_against_stats(Role role, const std::vector<std::filesystem::path>& actual,
                                     const std::filesystem::path& mean_file,
                                     const std::filesystem::path& golden_dir,
                                     const GoldenEntry& entry, const GoldenNoise& noise,
                                     const NoisyThresholds& thresholds,
                                     const std::filesystem::path& evidence_dir,
                                     const std::string& stem) {
  ImageCheck check{role,
                   ImageReference::golden,
                   actual.empty() ? std::filesystem::path() : actual.front(),
                   mean_file,
                   ImageVerdict::error,
                   {},
                   std::nullopt,
                   {},
                   std::nullopt};
  if (auto unusable = unusable_actual(check, actual)) return *unusable;
  NoisyImageStats golden;
  try {
    // noise.runs lies in 2 to 10^6 here: golden_noise_problem() refused it before otherwise.
    golden = read_stats_images(mean_file, golden_dir / noise.variance_file,
                               static_cast<int>(noise.runs), noise.inflation);
  } catch (const Error& e) {
    check.error = e.what();
    return check;
  }
  // Sweep 12: both images resized, their hashes updated, called the tracer's image DIFFERENT.
  if (golden.width != entry.width || golden.height != entry.height) {
    check.error = fmt::format("{} is {}x{}, but the manifest lists it at {}x{} ({})", entry.file,
                              golden.width, golden.height, entry.width, entry.height,
                              (golden_dir / "manifest.json").string());
    return check;
  }
  if (auto problem = nonsense_statistics(golden, mean_file, golden_dir / noise.variance_file)) {
    check.error = std::move(*problem);  // verdict error: the golden cannot judge
    return check;
  }
  return judged(check, actual, golden, thresholds, evidence_dir, stem);
}

}  // namespace raygate

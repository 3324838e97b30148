#include "compare/image_check.h"

#include <fmt/core.h>

#include "compare/noisy_image_check.h"
#include "compare/run_folder.h"
#include "core/error.h"

namespace raygate {

namespace {

std::string describe_settings(const GoldenEntry& e) {
  std::string text = e.scene + (e.size > 0 ? " size " + std::to_string(e.size) : "");
  if (e.width > 0) text += " at " + std::to_string(e.width) + "x" + std::to_string(e.height);
  if (!e.sampling.empty()) text += ", " + e.sampling + " sampling";
  return text;
}

bool same_settings(const GoldenEntry& golden, const GoldenEntry& rendered) {
  const bool same_resolution =
      rendered.width == 0 || (golden.width == rendered.width && golden.height == rendered.height);
  const bool same_sampling = rendered.sampling.empty() || golden.sampling == rendered.sampling;
  return golden.scene == rendered.scene && golden.size == rendered.size && same_resolution &&
         same_sampling;
}

// With nothing to compare against, the image is still read: a tracer that exited 0 but wrote
// an unreadable image, one with NaN pixels, or one of another size than the scene's, has failed
// on it, golden or not.
ImageCheck without_golden(Role role, const std::filesystem::path& actual,
                          const std::filesystem::path& expected, const std::string& why,
                          const GoldenEntry& rendered) {
  ImageCheck check{role, ImageReference::golden, actual, expected,    ImageVerdict::missing,
                   why,  std::nullopt,           {},     std::nullopt};
  if (auto gone = vanished_run_folder(actual)) {
    check.verdict = ImageVerdict::error;
    check.error = std::move(*gone);
    return check;
  }
  if (const std::string problem = unreadable_image(actual); !problem.empty()) {
    check.verdict = ImageVerdict::fail;
    check.error = problem;
    return check;
  }
  // The image against itself: every metric zero, but its NaN pixels counted.
  const ImageMetrics self = compare_images(actual, actual, {});
  if (self.nonfinite_pixels > 0) {
    check.verdict = ImageVerdict::fail;
    check.error = summarize(self);
    check.metrics = self;
  } else if (rendered.width > 0 && rendered.height > 0 &&
             (self.width != rendered.width || self.height != rendered.height)) {
    check.verdict = ImageVerdict::fail;
    check.error =
        fmt::format("{}: the image is {}x{}, but the scene renders at {}x{}", actual.string(),
                    self.width, self.height, rendered.width, rendered.height);
  }
  return check;
}

// Whose fault an image that cannot be compared is: the tracer's own image unreadable or with
// NaN pixels fails the check (exit 1); a broken reference (golden, base's image) means the
// check could not be made (error).
std::optional<std::string> broken_reference(const ImageMetrics& m,
                                            const std::filesystem::path& expected) {
  if (m.nonfinite_pixels > 0 || m.expected_nonfinite_pixels == 0) return std::nullopt;
  return fmt::format("{}: the reference has {} NaN/Inf pixels; nothing to compare with",
                     expected.string(), m.expected_nonfinite_pixels);
}

}  // namespace

std::string_view to_string(ImageReference reference) {
  return reference == ImageReference::base ? "base" : "golden";
}

std::optional<ImageReference> parse_image_reference(std::string_view word) {
  for (const ImageReference reference : {ImageReference::golden, ImageReference::base}) {
    if (to_string(reference) == word) return reference;
  }
  return std::nullopt;
}

std::string check_detail(const ImageCheck& check) {
  if (check.metrics) {
    const std::string what = summarize(*check.metrics);
    return check.error.empty() || check.error == what ? what : what + "; " + check.error;
  }
  if (check.noisy) {
    const std::string what = summarize(*check.noisy);
    return check.error.empty() ? what : what + "; " + check.error;
  }
  return check.error;
}

std::string check_label(const ImageCheck& check, std::string_view between) {
  std::string label = role_name(check.role);
  if (check.reference == ImageReference::golden) return label;
  return label.append(between).append(to_string(check.reference));
}

ImageCheck check_image(Role role, ImageReference reference, const std::filesystem::path& actual,
                       const std::filesystem::path& expected, const ImageThresholds& thresholds,
                       const std::filesystem::path& evidence_dir, const std::string& stem) {
  ImageCheck check{role, reference,    actual, expected,    ImageVerdict::error,
                   {},   std::nullopt, {},     std::nullopt};
  if (auto gone = vanished_run_folder(actual)) {
    check.error = std::move(*gone);
    return check;
  }
  if (std::string problem = unreadable_image(actual); !problem.empty()) {
    check.verdict = ImageVerdict::fail;
    check.error = std::move(problem);
    return check;
  }
  try {
    check.metrics = compare_images(actual, expected, thresholds);
  } catch (const Error& e) {
    check.error = e.what();  // the reference is unreadable
    return check;
  }
  if (auto problem = broken_reference(*check.metrics, expected)) {
    check.error = std::move(*problem);
    check.metrics.reset();  // no comparison happened: no numbers that look like one
    return check;
  }
  check.verdict = judge(*check.metrics, thresholds);
  if (check.failed()) {
    try {
      write_evidence(actual, expected, evidence_dir, stem);
      for (const char* kind : {"actual", "expected", "diff"}) {
        check.evidence.push_back(evidence_dir / (stem + "." + kind + ".png"));
      }
    } catch (const Error& e) {
      check.error = std::string("evidence not written: ") + e.what();
    }
  }
  return check;
}

namespace {

// A manifest of the suite being measured whose entry is not what bless wrote for it (another
// size, resolution, sampling or accel: edited): its golden cannot be trusted to judge, and an
// edit must not switch the check off as a golden of another suite is (docs/gate.md).
std::optional<std::string> edited_entry(const std::filesystem::path& golden_dir,
                                        const GoldenManifest& manifest,
                                        const GoldenEntry& rendered) {
  const GoldenEntry* entry = manifest.find(rendered.id);
  if (entry == nullptr || rendered.rendering_suite.empty() ||
      manifest.suite != rendered.rendering_suite || same_settings(*entry, rendered)) {
    return std::nullopt;
  }
  return fmt::format(
      "{}: the entry of '{}' is {}, but suite {} renders {} (edited after bless?); bless it "
      "again after looking at it",
      (golden_dir / "manifest.json").string(), rendered.id, describe_settings(*entry),
      manifest.suite, describe_settings(rendered));
}

// Why no golden of `manifest` judges the image of `rendered` (the same words for every scene of
// an empty set), or nullopt when one does.
std::optional<std::string> no_golden(const std::filesystem::path& golden_dir,
                                     const GoldenManifest& manifest, const GoldenEntry& rendered) {
  const std::string& id = rendered.id;
  const GoldenEntry* entry = manifest.find(id);
  if (manifest.entries.empty()) {
    // A mistyped --golden-dir checks no image either: the words say which it was.
    std::error_code absent;
    if (!std::filesystem::exists(golden_dir, absent) && !absent)
      return "no goldens: " + golden_dir.string() + " does not exist";
    return "no goldens in " + golden_dir.string() + " (none blessed yet)";
  }
  // A file that cannot even be looked at (a symbolic link loop) is there: golden_file_problem
  // says why it cannot judge (ERROR), where a throw here lost the whole measurement.
  std::error_code unreadable;
  if (entry == nullptr ||
      (!std::filesystem::exists(golden_dir / entry->file, unreadable) && !unreadable)) {
    return "no golden image for '" + id + "' in " + golden_dir.string();
  }
  if (!same_settings(*entry, rendered)) {
    return "the golden of '" + id + "' in " + golden_dir.string() + " is " +
           describe_settings(*entry) + ", but this suite renders " + describe_settings(rendered) +
           "; bless this suite's goldens into a directory of their own (--golden-dir DIR)";
  }
  return std::nullopt;
}

// A scene's golden as either check (one image, or the statistics of several runs) needs it.
struct GoldenLookup {
  std::filesystem::path expected;      // the manifest's file, or where one would be
  std::optional<std::string> missing;  // why no golden judges the image; nullopt when one does
  std::string stem;                    // of the evidence files: <scene>.<role>-vs-golden
  const GoldenEntry* entry = nullptr;  // set when it is not missing
  std::optional<std::string> edited;   // why the manifest's entry cannot be trusted (edited_entry)
};

// A golden that does not match its manifest judges nothing: the check could not be made.
ImageCheck untrusted_golden(Role role, const std::filesystem::path& actual,
                            const std::filesystem::path& expected, std::string why) {
  return {role,           ImageReference::golden, actual, expected,    ImageVerdict::error,
          std::move(why), std::nullopt,           {},     std::nullopt};
}

// `extension` names the file a scene without an entry would have, so that a report of a missing
// golden still shows a path.
GoldenLookup look_up_golden(Role role, const std::filesystem::path& golden_dir,
                            const GoldenManifest& manifest, const GoldenEntry& rendered,
                            std::string_view extension) {
  const std::string& id = rendered.id;
  const GoldenEntry* entry = manifest.find(id);
  return {golden_dir / (entry != nullptr ? entry->file : id + std::string(extension)),
          no_golden(golden_dir, manifest, rendered), id + "." + role_name(role) + "-vs-golden",
          entry, edited_entry(golden_dir, manifest, rendered)};
}

}  // namespace

ImageCheck check_runs_against_golden(Role role, const std::vector<std::filesystem::path>& actual,
                                     const std::filesystem::path& golden_dir,
                                     const GoldenManifest& manifest, const GoldenEntry& rendered,
                                     const NoisyThresholds& thresholds,
                                     const std::filesystem::path& evidence_dir) {
  const GoldenLookup golden = look_up_golden(role, golden_dir, manifest, rendered, ".exr");
  const std::filesystem::path first = actual.empty() ? std::filesystem::path() : actual.front();
  if (golden.edited) return untrusted_golden(role, first, golden.expected, *golden.edited);
  if (golden.missing) {
    return without_golden(role, first, golden.expected, *golden.missing, rendered);
  }
  const auto noise = manifest.noise.find(rendered.id);
  if (noise == manifest.noise.end()) {
    return without_golden(role, first, golden.expected,
                          "the golden of '" + rendered.id + "' in " + golden_dir.string() +
                              " is one image, not the statistics of several runs a Monte Carlo "
                              "tracer is judged by; bless it from a run of this adapter (raygate "
                              "golden bless --from-run RESULTS.json)",
                          rendered);
  }
  const GoldenNoise& stats = noise->second;
  for (const auto& [file, sha] : {std::pair(golden.entry->file, golden.entry->sha256),
                                  std::pair(stats.variance_file, stats.variance_sha256)}) {
    if (auto problem = golden_file_problem(golden_dir, file, sha)) {
      return untrusted_golden(role, first, golden.expected, std::move(*problem));
    }
  }
  const std::string where = (golden_dir / "manifest.json").string() + ": '" + rendered.id + "'";
  if (auto problem = golden_noise_problem(stats, where)) {
    return untrusted_golden(role, first, golden.expected, std::move(*problem));
  }
  return check_noisy_against_stats(role, actual, golden.expected, golden_dir, *golden.entry,
                                   noise->second, thresholds, evidence_dir, golden.stem);
}

ImageCheck check_against_golden(Role role, const std::filesystem::path& actual,
                                const std::filesystem::path& golden_dir,
                                const GoldenManifest& manifest, const GoldenEntry& rendered,
                                const ImageThresholds& thresholds,
                                const std::filesystem::path& evidence_dir) {
  const GoldenLookup golden = look_up_golden(role, golden_dir, manifest, rendered, ".png");
  if (golden.edited) return untrusted_golden(role, actual, golden.expected, *golden.edited);
  if (golden.missing) {
    return without_golden(role, actual, golden.expected, *golden.missing, rendered);
  }
  if (auto problem = golden_file_problem(golden_dir, golden.entry->file, golden.entry->sha256)) {
    return untrusted_golden(role, actual, golden.expected, std::move(*problem));
  }
  ImageCheck check = check_image(role, ImageReference::golden, actual, golden.expected, thresholds,
                                 evidence_dir, golden.stem);
  // The manifest's size is what look_up_golden matched the render by: a golden of another size
  // under those words is a manifest that does not describe its image.
  const GoldenEntry& entry = *golden.entry;
  if (check.metrics && (check.metrics->expected_width != entry.width ||
                        check.metrics->expected_height != entry.height)) {
    return untrusted_golden(role, actual, golden.expected,
                            fmt::format("{} is {}x{}, but the manifest lists it at {}x{} ({})",
                                        entry.file, check.metrics->expected_width,
                                        check.metrics->expected_height, entry.width, entry.height,
                                        (golden_dir / "manifest.json").string()));
  }
  return check;
}

}  // namespace raygate

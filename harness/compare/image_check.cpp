#include "compare/image_check.h"

#include <OpenImageIO/imagebuf.h>

#include "core/error.h"

namespace raygate {

namespace {

std::string_view verdict_name(ImageVerdict verdict) {
  switch (verdict) {
    case ImageVerdict::pass: return "pass";
    case ImageVerdict::warn: return "warn";
    case ImageVerdict::fail: return "fail";
  }
  return "fail";
}

std::string describe_settings(const GoldenEntry& e) {
  std::string text = e.scene + (e.size > 0 ? " size " + std::to_string(e.size) : "");
  if (e.width > 0) text += " at " + std::to_string(e.width) + "x" + std::to_string(e.height);
  if (!e.sampling.empty()) text += ", " + e.sampling + " sampling";
  return text;
}

bool same_settings(const GoldenEntry& golden, const GoldenEntry& rendered) {
  const bool same_resolution = rendered.width == 0 ||
                               (golden.width == rendered.width && golden.height == rendered.height);
  const bool same_sampling = rendered.sampling.empty() || golden.sampling == rendered.sampling;
  return golden.scene == rendered.scene && golden.size == rendered.size && same_resolution &&
         same_sampling;
}

// Why OpenImageIO cannot decode `image`, or "" when it can.
std::string unreadable(const std::filesystem::path& image) {
  OIIO_NAMESPACE::ImageBuf buf(image.string());
  if (buf.read(0, 0, true, OIIO_NAMESPACE::TypeDesc::FLOAT)) return {};
  return image.string() + ": cannot read image: " + buf.geterror();
}

// With nothing to compare against, the image is still read: an unreadable image is an error
// even when no golden exists, not a "missing" that passes.
ImageCheck without_golden(const std::string& role, const std::filesystem::path& actual,
                          const std::filesystem::path& expected, const std::string& why) {
  ImageCheck check{role, "golden", actual, expected, "missing", why, std::nullopt, {}};
  if (const std::string problem = unreadable(actual); !problem.empty()) {
    check.verdict = "error";
    check.error = problem + " (" + why + ")";
  }
  return check;
}

}  // namespace

ImageCheck check_image(const std::string& role, const std::string& reference,
                       const std::filesystem::path& actual, const std::filesystem::path& expected,
                       const ImageThresholds& thresholds, const std::filesystem::path& evidence_dir,
                       const std::string& stem) {
  ImageCheck check{role, reference, actual, expected, "error", {}, std::nullopt, {}};
  try {
    check.metrics = compare_images(actual, expected, thresholds);
  } catch (const Error& e) {
    check.error = e.what();
    return check;
  }
  check.verdict = std::string(verdict_name(judge(*check.metrics, thresholds)));
  if (check.verdict == "fail") {
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

ImageCheck check_against_golden(const std::string& role, const std::filesystem::path& actual,
                                const std::filesystem::path& golden_dir,
                                const GoldenManifest& manifest, const GoldenEntry& rendered,
                                const ImageThresholds& thresholds,
                                const std::filesystem::path& evidence_dir) {
  const std::string& id = rendered.id;
  const GoldenEntry* entry = manifest.find(id);
  const std::filesystem::path expected =
      golden_dir / (entry != nullptr ? entry->file : id + ".png");
  if (entry == nullptr || !std::filesystem::exists(expected)) {
    return without_golden(role, actual, expected,
                          "no golden image for '" + id + "' in " + golden_dir.string());
  }
  if (!same_settings(*entry, rendered)) {
    return without_golden(
        role, actual, expected,
        "the golden of '" + id + "' in " + golden_dir.string() + " is " +
            describe_settings(*entry) + ", but this suite renders " + describe_settings(rendered) +
            "; bless goldens for this suite in a directory of their own (raygate golden bless "
            "--suite SUITE --golden-dir DIR)");
  }
  return check_image(role, "golden", actual, expected, thresholds, evidence_dir,
                     id + "." + role + "-vs-golden");
}

}  // namespace raygate

#include "compare/image_check.h"

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
                                const GoldenManifest& manifest, const std::string& id,
                                const ImageThresholds& thresholds,
                                const std::filesystem::path& evidence_dir) {
  const GoldenEntry* entry = manifest.find(id);
  const std::filesystem::path expected =
      golden_dir / (entry != nullptr ? entry->file : id + ".png");
  if (entry == nullptr || !std::filesystem::exists(expected)) {
    ImageCheck check{role, "golden", actual, expected, "missing", {}, std::nullopt, {}};
    check.error = "no golden image for '" + id + "' in " + golden_dir.string();
    return check;
  }
  return check_image(role, "golden", actual, expected, thresholds, evidence_dir,
                     id + "." + role + "-vs-golden");
}

}  // namespace raygate

// Image error between a tracer's picture and a reference (golden or base revision), through
// OpenImageIO on float pixels, in idiff's terms: a pixel "fails" when any channel differs by
// more than fail_threshold, and the image fails when more than fail_percent of its pixels do or
// any channel differs by more than hard_fail.
#pragma once

#include <array>
#include <filesystem>
#include <string>

#include "compare/image_verdict.h"

namespace raygate {

struct ImageThresholds {
  double fail_threshold = 0.004;  // per channel, in [0,1] units (idiff -fail)
  double fail_percent = 0.02;     // percent of pixels allowed over fail_threshold (-failpercent)
  double hard_fail = 1e30;        // any channel over this fails outright (-hardfail)
  double warn_threshold = 0.004;  // idiff -warn
};

struct ImageMetrics {
  bool size_mismatch = false;
  int width = 0, height = 0;                    // actual
  int expected_width = 0, expected_height = 0;  // reference
  double mean_error = 0.0;
  double rms_error = 0.0;
  double psnr_db = 0.0;  // infinite when identical
  double max_error = 0.0;
  int max_x = 0, max_y = 0, max_channel = 0;
  double max_actual_value = 0.0, max_expected_value = 0.0;  // the two values at the worst pixel
  long pixels_over_warn = 0;
  long pixels_over_fail = 0;
  double percent_over_fail = 0.0;
  double mean_luminance_actual = 0.0;
  double mean_luminance_expected = 0.0;
  long nonfinite_values = 0;  // NaN or Inf channels in the actual image
  // Pixels of the actual image with a NaN or Inf channel, and the first of them: a broken
  // render, whatever the comparison says (a NaN difference is over no threshold).
  long nonfinite_pixels = 0;
  int nonfinite_x = 0, nonfinite_y = 0;
  long expected_nonfinite_pixels = 0;  // the same in the reference: no reference at all

  bool identical() const {
    return !size_mismatch && max_error == 0.0 && nonfinite_values == 0 && nonfinite_pixels == 0;
  }
  double luminance_bias() const { return mean_luminance_actual - mean_luminance_expected; }
};

// Reads both images (any format OpenImageIO reads) and compares their RGB channels. Throws
// UsageError naming the file if either cannot be read.
// Why `image` cannot be decoded, in one line ("" when it can): image libraries (libpng) report
// over several lines, and a report's table cell holds one.
std::string unreadable_image(const std::filesystem::path& image);

ImageMetrics compare_images(const std::filesystem::path& actual,
                            const std::filesystem::path& expected,
                            const ImageThresholds& thresholds);

// pass, warn or fail (the other verdicts are for checks that compared nothing).
ImageVerdict judge(const ImageMetrics& metrics, const ImageThresholds& thresholds);

// One line for a report: "max 0.031 at (12,40) ch 1: 0.52 vs 0.49; 0.3% over 0.004; PSNR 41.2 dB";
// an image with NaN or Inf pixels says so first: "12 NaN/Inf pixels of 16384, first at (3,4)".
std::string summarize(const ImageMetrics& metrics);

// Writes <stem>.actual.png, <stem>.expected.png and <stem>.diff.png (|actual-expected| x 16)
// into `dir`: the evidence a reviewer looks at when an image check fails.
void write_evidence(const std::filesystem::path& actual, const std::filesystem::path& expected,
                    const std::filesystem::path& dir, const std::string& stem);

}  // namespace raygate

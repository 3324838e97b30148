// The Monte Carlo image verdict's line (compare/noisy_image_compare.h summarize): the same words
// on the console, in every report and in `golden verify`, made from the typed comparison.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "compare/noisy_image_compare.h"

namespace raygate {

namespace {

constexpr const char* kChannelNames[3] = {"R", "G", "B"};

// A change of a black reference can be 10^40 %: past a million per cent, three significant digits.
std::string percent(double relative) {
  const double percent = 100 * relative;
  return std::abs(percent) < 1e6 ? fmt::format("{:+.2f}%", percent)
                                 : fmt::format("{:+.3g}%", percent);
}

std::string interval_text(const RelativeChange& c) {
  return fmt::format("{} [{}, {}]", percent(c.change), percent(c.low), percent(c.high));
}

std::string tolerance_text(const NoisyComparison& c) {
  return fmt::format("±{:.3g}% image tolerance", 100 * c.tolerance);
}

std::string tile_name(int tile_px) {
  return tile_px == kWholeImage ? "whole image" : fmt::format("{} px", tile_px);
}

// "image mean -0.20% [-0.61%, +0.21%] (90%); 8 vs 8 runs"
std::string evidence_text(const NoisyComparison& c) {
  return fmt::format("image mean {} ({:.0f}%); {} vs {} runs", interval_text(c.image),
                     100 * c.confidence, c.actual_runs, c.expected_runs);
}

// The whole image's failure when it has one (a global change reads as one, even where a small
// tile's test happens to be surer), else the surest tile's.
std::string failed_text(const NoisyComparison& c) {
  const auto whole = std::find_if(c.biased.begin(), c.biased.end(),
                                  [](const BiasedTile& t) { return t.tile_px == kWholeImage; });
  const BiasedTile& w = whole != c.biased.end() ? *whole : c.biased.front();
  if (w.tile_px == kWholeImage) {
    return fmt::format("fail (beyond the {}): the whole image {} {}; {}; {} of {} tests failed",
                       tolerance_text(c), kChannelNames[w.channel], interval_text(w.change),
                       evidence_text(c), c.biased_count, c.tests);
  }
  return fmt::format(
      "fail (biased): {} tile at ({},{}) {}x{} {} {}, beyond its {:.3g}% minimum; {} of {} tests "
      "failed; {}; {}",
      tile_name(w.tile_px), w.rect.x, w.rect.y, w.rect.width, w.rect.height,
      kChannelNames[w.channel], interval_text(w.change), 100 * w.min_effect, c.biased_count,
      c.tests, evidence_text(c), tolerance_text(c));
}

std::string resolves_text(const NoisyComparison& c) {
  std::string text;
  for (const ScaleReport& r : c.scales) {
    text += fmt::format("{}{} {:.2g}%", text.empty() ? "" : ", ", tile_name(r.tile_px),
                        100 * r.detectable);
  }
  return text;
}

std::string inconclusive_text(const NoisyComparison& c) {
  if (c.tests == 0) {
    return fmt::format("inconclusive ({} vs {} runs: {})", c.actual_runs, c.expected_runs,
                       c.why_inconclusive);
  }
  const std::string more =
      std::isfinite(c.samples_factor)
          ? fmt::format("about {:.1f}x the samples would decide it, e.g. {} runs a side",
                        c.samples_factor, c.runs_needed)
          : std::string("no number of runs is sure to decide it");
  return fmt::format("inconclusive ({} the {}; {}): {}; channels R {}, G {}, B {}",
                     c.why_inconclusive, tolerance_text(c), more, evidence_text(c),
                     interval_text(c.channels[0]), interval_text(c.channels[1]),
                     interval_text(c.channels[2]));
}

}  // namespace

std::string summarize(const NoisyComparison& c) {
  if (c.size_mismatch) return "fail (size " + *c.size_mismatch + ")";
  if (c.verdict == NoisyVerdict::fail && !c.biased.empty()) return failed_text(c);
  if (c.verdict == NoisyVerdict::pass) {
    return fmt::format("pass (within the {}): {}; {} tests, no tile biased, resolves {}",
                       tolerance_text(c), evidence_text(c), c.tests, resolves_text(c));
  }
  return inconclusive_text(c);
}

}  // namespace raygate

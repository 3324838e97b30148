#include "compare/noisy_image_compare.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/enum_words.h"
#include "measure/probability.h"

namespace raygate {

namespace {

constexpr double kLuminance[3] = {0.2126, 0.7152, 0.0722};
constexpr const char* kChannelNames[3] = {"R", "G", "B"};
constexpr double kInterval = 0.95;  // reported intervals

// One tile's channel, both sides.
struct TileTest {
  std::size_t scale = 0;  // index into the thresholds' scales
  TileRect rect;
  int channel = 0;
  double difference = 0.0;  // actual - expected
  double standard_error = 0.0;
  double reference = 1.0;  // what the difference is relative to
  double z = 0.0;
  double p = 1.0;
  double weight = 1.0;  // its share of alpha (all weights sum to 1)
};

double image_mean(const NoisyImageStats& stats) {
  double sum = 0;
  for (const float v : stats.mean) sum += v;
  return stats.mean.empty() ? 0.0 : sum / static_cast<double>(stats.mean.size());
}

TileTest make_test(const NoisyImageStats& actual, const NoisyImageStats& expected,
                   std::size_t scale, int tile_px, const TileRect& rect, int channel,
                   double dark) {
  const TileEstimate a = estimate_tile(actual, rect, channel, tile_px);
  const TileEstimate b = estimate_tile(expected, rect, channel, tile_px);
  TileTest t{scale, rect, channel, a.mean - b.mean,
             std::sqrt(a.variance_of_mean + b.variance_of_mean), std::max(b.mean, dark)};
  if (t.standard_error > 0) {
    t.z = t.difference / t.standard_error;
  } else if (std::abs(t.difference) > 1e-7 * t.reference) {
    // No noise on either side and still a difference: as certain as a difference gets.
    t.z = std::copysign(std::numeric_limits<double>::infinity(), t.difference);
  }
  t.p = two_sided_p(t.z);
  return t;
}

// Weighted Holm (Holm 1979): in order of p / weight, a test is rejected while
// p <= alpha * weight / (the weight of the tests not yet rejected); the first that is not stops
// it. Controls the family-wise error rate at alpha under any dependence between the tests.
std::vector<bool> holm_rejections(const std::vector<TileTest>& tests, double alpha) {
  std::vector<std::size_t> order(tests.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return tests[a].p / tests[a].weight < tests[b].p / tests[b].weight;
  });
  std::vector<bool> rejected(tests.size(), false);
  double remaining = 0;
  for (const TileTest& t : tests) remaining += t.weight;
  for (const std::size_t i : order) {
    if (tests[i].p > alpha * tests[i].weight / remaining) break;
    rejected[i] = true;
    remaining -= tests[i].weight;
  }
  return rejected;
}

BiasedTile biased_tile(const TileTest& t, int tile_px) {
  const double half = normal_quantile(0.5 + kInterval / 2) * t.standard_error;
  return {tile_px,
          t.rect,
          t.channel,
          t.difference / t.reference,
          (t.difference - half) / t.reference,
          (t.difference + half) / t.reference,
          t.z,
          t.p};
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// What each scale can see: the relative change its median tile finds with probability `power`
// when tested alone at the family's first Holm threshold, alpha / tests.
std::vector<ScaleReport> scale_reports(const std::vector<TileTest>& tests,
                                       const std::vector<TileScale>& scales,
                                       const std::vector<std::size_t>& used,
                                       const NoisyThresholds& thresholds) {
  std::vector<ScaleReport> reports;
  for (const std::size_t s : used) {
    std::vector<double> relative_errors;
    double weight = 0;
    for (const TileTest& t : tests) {
      if (t.scale != s) continue;
      relative_errors.push_back(t.standard_error / t.reference);
      weight = t.weight;
    }
    const double z_needed = normal_quantile(1 - thresholds.alpha * weight / 2) +
                            normal_quantile(thresholds.power);
    reports.push_back({scales[s].tile_px, relative_errors.size() / 3, scales[s].min_effect,
                       z_needed * median(relative_errors), scales[s].must_resolve});
  }
  return reports;
}

// The whole image's luminance change; its standard error taken as if the channels' errors were
// fully correlated (they share every path), which can only widen the interval.
void whole_image_change(const NoisyImageStats& actual, const NoisyImageStats& expected,
                        NoisyComparison& out) {
  const TileRect all{0, 0, actual.width, actual.height};
  double difference = 0, reference = 0, error = 0;
  for (int c = 0; c < 3; ++c) {
    const TileEstimate a = estimate_tile(actual, all, c, kWholeImage);
    const TileEstimate b = estimate_tile(expected, all, c, kWholeImage);
    difference += kLuminance[c] * (a.mean - b.mean);
    reference += kLuminance[c] * b.mean;
    error += kLuminance[c] * std::sqrt(a.variance_of_mean + b.variance_of_mean);
  }
  if (!(reference > 0)) return;
  const double half = normal_quantile(0.5 + kInterval / 2) * error;
  out.image_change = difference / reference;
  out.image_low = (difference - half) / reference;
  out.image_high = (difference + half) / reference;
}

void judge_power(NoisyComparison& out) {
  for (const ScaleReport& r : out.scales) {
    if (!(r.must_resolve > 0) || r.detectable <= r.must_resolve) continue;
    const double factor = std::pow(r.detectable / r.must_resolve, 2);
    if (factor > out.samples_factor) {
      out.samples_factor = factor;
      out.why_inconclusive = fmt::format(
          "{} resolves {:.2g}%, needs {:.2g}%",
          r.tile_px == kWholeImage ? std::string("the whole image")
                                   : fmt::format("{} px tiles", r.tile_px),
          100 * r.detectable, 100 * r.must_resolve);
    }
  }
}

std::string tile_name(int tile_px) {
  return tile_px == kWholeImage ? "whole image" : fmt::format("{} px", tile_px);
}

std::string percent(double relative) { return fmt::format("{:+.2f}%", 100 * relative); }

// The verdicts' words, as documents and reports write them.
constexpr EnumWords<NoisyVerdict, 3> kVerdictWords{{
    {NoisyVerdict::pass, "pass"}, {NoisyVerdict::fail, "fail"},
    {NoisyVerdict::inconclusive, "inconclusive"}}};

}  // namespace

std::string_view to_string(NoisyVerdict verdict) {
  return word_of(kVerdictWords, verdict, "inconclusive");
}

double two_sided_p(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }

NoisyComparison compare_noisy(const NoisyImageStats& actual, const NoisyImageStats& expected,
                              const NoisyThresholds& thresholds) {
  NoisyComparison out;
  out.width = actual.width;
  out.height = actual.height;
  out.actual_runs = actual.runs;
  out.expected_runs = expected.runs;
  if (actual.width != expected.width || actual.height != expected.height) {
    out.size_mismatch = fmt::format("{}x{} against {}x{}", actual.width, actual.height,
                                    expected.width, expected.height);
    out.verdict = NoisyVerdict::fail;
    return out;
  }
  if (actual.runs < thresholds.min_runs || expected.runs < thresholds.min_runs) {
    out.why_inconclusive = fmt::format("{} vs {} runs: each side needs at least {} to measure its noise",
                                       actual.runs, expected.runs, thresholds.min_runs);
    return out;  // inconclusive
  }
  const double dark = thresholds.dark_floor * image_mean(expected);
  std::vector<int> sides;
  for (const TileScale& s : thresholds.scales) sides.push_back(s.tile_px);
  const std::vector<int> present = tile_scales(actual.width, actual.height, sides);
  std::vector<std::size_t> used;
  std::vector<TileTest> tests;
  for (std::size_t s = 0; s < thresholds.scales.size(); ++s) {
    const int tile_px = thresholds.scales[s].tile_px;
    if (std::find(present.begin(), present.end(), tile_px) == present.end()) continue;
    used.push_back(s);
    for (const TileRect& rect : tile_grid(actual.width, actual.height, tile_px)) {
      for (int c = 0; c < 3; ++c) tests.push_back(make_test(actual, expected, s, tile_px, rect, c, dark));
    }
  }
  out.tests = tests.size();
  // Each scale an equal share of alpha, split evenly over its tiles and channels.
  std::vector<double> in_scale(thresholds.scales.size(), 0.0);
  for (const TileTest& t : tests) in_scale[t.scale] += 1;
  for (TileTest& t : tests) t.weight = 1.0 / (static_cast<double>(used.size()) * in_scale[t.scale]);
  const std::vector<bool> rejected = holm_rejections(tests, thresholds.alpha);
  for (std::size_t i = 0; i < tests.size(); ++i) {
    const TileScale& scale = thresholds.scales[tests[i].scale];
    if (rejected[i] && std::abs(tests[i].difference / tests[i].reference) >= scale.min_effect) {
      out.biased.push_back(biased_tile(tests[i], scale.tile_px));
    }
  }
  std::sort(out.biased.begin(), out.biased.end(),
            [](const BiasedTile& a, const BiasedTile& b) { return std::abs(a.z) > std::abs(b.z); });
  whole_image_change(actual, expected, out);
  out.scales = scale_reports(tests, thresholds.scales, used, thresholds);
  judge_power(out);
  if (!out.biased.empty()) out.verdict = NoisyVerdict::fail;
  else if (out.samples_factor > 1) out.verdict = NoisyVerdict::inconclusive;
  else out.verdict = NoisyVerdict::pass;
  return out;
}

std::string summarize(const NoisyComparison& c) {
  if (c.size_mismatch) return "fail (size " + *c.size_mismatch + ")";
  const std::string runs = fmt::format("{} vs {} runs", c.actual_runs, c.expected_runs);
  if (c.tests == 0) return "inconclusive (too noisy: " + c.why_inconclusive + ")";
  const std::string image = fmt::format("image mean {} [{}, {}]", percent(c.image_change),
                                        percent(c.image_low), percent(c.image_high));
  if (c.verdict == NoisyVerdict::fail) {
    const BiasedTile& w = c.biased.front();
    const std::string where =
        w.tile_px == kWholeImage
            ? std::string("the whole image")
            : fmt::format("{} tile at ({},{}) {}x{}", tile_name(w.tile_px), w.rect.x, w.rect.y,
                          w.rect.width, w.rect.height);
    return fmt::format("fail (biased): {} of {} tiles x channels; worst {} {} {} [{}, {}]; {}; {}",
                       c.biased.size(), c.tests, where, kChannelNames[w.channel],
                       percent(w.relative_change), percent(w.low), percent(w.high), image, runs);
  }
  std::string resolves;
  for (const ScaleReport& r : c.scales) {
    resolves += fmt::format("{}{} {:.2g}%", resolves.empty() ? "" : ", ", tile_name(r.tile_px),
                            100 * r.detectable);
  }
  if (c.verdict == NoisyVerdict::inconclusive) {
    const int needed = static_cast<int>(std::ceil(c.samples_factor * std::min(c.actual_runs, c.expected_runs)));
    return fmt::format(
        "inconclusive (too noisy: {}; needs about {:.1f}x the samples, e.g. {} runs a side); {}; {}",
        c.why_inconclusive, c.samples_factor, needed, image, runs);
  }
  return fmt::format("pass (same within noise): {}; {}; {} tests, resolves {}", image, runs,
                     c.tests, resolves);
}

}  // namespace raygate

#include "compare/noisy_image_compare.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "compare/noisy_image_check.h"  // to_image_verdict: the verdicts' words
#include "measure/probability.h"

namespace raygate {

namespace {

constexpr double kLuminance[3] = {0.2126, 0.7152, 0.0722};
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// One tile's channel, both sides.
struct TileTest {
  std::size_t scale = 0;  // index into the scales used; the whole image is the last
  int tile_px = kWholeImage;
  TileRect rect;
  int channel = 0;
  double difference = 0.0;  // actual - expected
  double standard_error = 0.0;
  double reference = 1.0;   // what the difference is relative to
  double min_effect = 0.0;  // relative: a rejected test fails the image only from here on
  double z = 0.0;
  double p = 1.0;
  double weight = 1.0;  // its share of alpha (all weights sum to 1)

  double relative() const { return difference / reference; }
  double relative_error() const { return standard_error / reference; }
};

double upper_tail(double z) { return 0.5 * std::erfc(z / std::sqrt(2.0)); }

double image_mean(const NoisyImageStats& stats) {
  double sum = 0;
  for (const float v : stats.mean) sum += v;
  return stats.mean.empty() ? 0.0 : sum / static_cast<double>(stats.mean.size());
}

// The tile's channel on both sides, tested against "no change at all" (the local-bias test).
TileTest make_test(const NoisyImageStats& actual, const NoisyImageStats& expected,
                   std::size_t scale, int tile_px, const TileRect& rect, int channel, double dark) {
  const TileEstimate a = estimate_tile(actual, rect, channel, tile_px);
  const TileEstimate b = estimate_tile(expected, rect, channel, tile_px);
  // The floor of 1e-30 keeps a black reference's relative change a number (huge), not NaN.
  TileTest t{scale,
             tile_px,
             rect,
             channel,
             a.mean - b.mean,
             std::sqrt(a.variance_of_mean + b.variance_of_mean),
             std::max({b.mean, dark, 1e-30})};
  if (t.standard_error > 0) {
    t.z = t.difference / t.standard_error;
  } else if (std::abs(t.difference) > 1e-7 * t.reference) {
    // No noise on either side and still a difference: as certain as a difference gets.
    t.z = std::copysign(kInfinity, t.difference);
  }
  t.p = two_sided_p(t.z);
  return t;
}

// The whole image's channel tested against "the change lies within ±tolerance": the p of the
// worst case on that boundary, P(|estimate| >= observed | change = ±tolerance).
void test_against_tolerance(TileTest& t, double tolerance) {
  const double r = std::abs(t.relative());
  const double s = t.relative_error();
  t.min_effect = tolerance;
  if (s > 0) {
    t.z = std::copysign((r - tolerance) / s, t.difference);
    t.p = std::min(1.0, upper_tail((r - tolerance) / s) + upper_tail((r + tolerance) / s));
  } else {
    t.z = r > tolerance ? std::copysign(kInfinity, t.difference) : 0.0;
    t.p = r > tolerance ? 0.0 : 1.0;
  }
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

RelativeChange interval(double change, double error, double z) {
  return {change, change - z * error, change + z * error};
}

BiasedTile biased_tile(const TileTest& t, double z_interval) {
  return {t.tile_px,    t.rect, t.channel, interval(t.relative(), t.relative_error(), z_interval),
          t.min_effect, t.z,    t.p};
}

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<long>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

// What each scale can see: the relative change its median tile finds with probability `power`
// when tested alone at its Holm weight.
std::vector<ScaleReport> scale_reports(const std::vector<TileTest>& tests, std::size_t scales,
                                       const NoisyThresholds& thresholds) {
  std::vector<ScaleReport> reports;
  for (std::size_t s = 0; s < scales; ++s) {
    std::vector<double> relative_errors;
    double weight = 0;
    int tile_px = kWholeImage;
    for (const TileTest& t : tests) {
      if (t.scale != s) continue;
      relative_errors.push_back(t.relative_error());
      weight = t.weight;
      tile_px = t.tile_px;
    }
    const double z_needed =
        normal_quantile(1 - thresholds.alpha * weight / 2) + normal_quantile(thresholds.power);
    reports.push_back({tile_px, relative_errors.size() / 3, z_needed * median(relative_errors)});
  }
  return reports;
}

// Every test of the image: the local-bias tests of each tile scale, then the whole image's
// three against the tolerance; each scale an equal share of alpha, split over its tests.
std::vector<TileTest> image_tests(const NoisyImageStats& actual, const NoisyImageStats& expected,
                                  const NoisyThresholds& thresholds, std::size_t& scales) {
  const double dark = thresholds.dark_floor * image_mean(expected);
  std::vector<int> sides;
  for (const TileScale& s : thresholds.tiles) sides.push_back(s.tile_px);
  std::vector<TileTest> tests;
  scales = 0;
  for (const int tile_px : tile_scales(actual.width, actual.height, sides)) {
    const auto scale = std::find_if(thresholds.tiles.begin(), thresholds.tiles.end(),
                                    [&](const TileScale& s) { return s.tile_px == tile_px; });
    const std::size_t first = tests.size();
    for (const TileRect& rect : tile_grid(actual.width, actual.height, tile_px)) {
      for (int c = 0; c < 3; ++c) {
        TileTest t = make_test(actual, expected, scales, tile_px, rect, c, dark);
        if (tile_px == kWholeImage) test_against_tolerance(t, thresholds.tolerance);
        else t.min_effect = scale->tolerance_multiple * thresholds.tolerance;
        tests.push_back(t);
      }
    }
    for (std::size_t i = first; i < tests.size(); ++i) {
      tests[i].weight = 1.0 / static_cast<double>(tests.size() - first);
    }
    ++scales;
  }
  for (TileTest& t : tests) t.weight /= static_cast<double>(scales);
  return tests;
}

// The luminance mean's change; its standard error taken as if the channels' errors were fully
// correlated (they share every path), which can only widen the interval.
RelativeChange luminance_change(const std::vector<TileTest>& whole, double z) {
  double difference = 0, reference = 0, error = 0;
  for (const TileTest& t : whole) {
    difference += kLuminance[t.channel] * t.difference;
    reference += kLuminance[t.channel] * t.reference;
    error += kLuminance[t.channel] * t.standard_error;
  }
  return interval(difference / reference, error / reference, z);
}

bool within(const RelativeChange& c, double tolerance) {
  return c.low >= -tolerance && c.high <= tolerance;
}

// About how many times the samples would decide an undecided image, projected from the
// estimates: every channel's interval inside the tolerance (pass), or one channel shown beyond
// it at its Holm share (fail), whichever needs fewer.
void project_samples(const std::vector<TileTest>& whole, const NoisyThresholds& thresholds,
                     NoisyComparison& out) {
  const double tolerance = thresholds.tolerance;
  const double z_pass = normal_quantile(1 - thresholds.equivalence_alpha);
  const double z_fail = normal_quantile(1 - thresholds.alpha * whole.front().weight);
  double to_pass = 1.0, to_fail = kInfinity;
  int deciding = 0;
  for (const TileTest& t : whole) {
    const double r = std::abs(t.relative()), s = t.relative_error();
    const double pass = r < tolerance ? std::pow(z_pass * s / (tolerance - r), 2) : kInfinity;
    const double fail = r > tolerance ? std::pow(z_fail * s / (r - tolerance), 2) : kInfinity;
    if (pass > to_pass) {
      to_pass = pass;
      deciding = t.channel;
    }
    to_fail = std::min(to_fail, fail);
  }
  out.samples_factor = std::max(1.0, std::min(to_pass, to_fail));
  const int runs = std::max(out.actual_runs, out.expected_runs);
  // Beyond a billion runs a side no budget decides it: said as no number at all.
  if (!(out.samples_factor * runs < 1e9)) out.samples_factor = kInfinity;
  out.runs_needed = std::isfinite(out.samples_factor)
                        ? static_cast<int>(std::ceil(out.samples_factor * runs))
                        : 0;
  out.why_inconclusive = to_fail < to_pass
                             ? "the whole image is shown neither within nor beyond"
                             : std::string("channel ") + "RGB"[deciding] + " is not shown within";
  if (!std::isfinite(std::min(to_pass, to_fail))) {
    out.why_inconclusive = "the whole image's change is estimated right at";
  }
}

void judge(const std::vector<TileTest>& tests, const NoisyThresholds& thresholds,
           NoisyComparison& out) {
  const std::vector<bool> rejected = holm_rejections(tests, thresholds.alpha);
  const double z_interval = normal_quantile(1 - thresholds.equivalence_alpha);
  for (std::size_t i = 0; i < tests.size(); ++i) {
    if (rejected[i] && std::abs(tests[i].relative()) >= tests[i].min_effect) {
      out.biased.push_back(biased_tile(tests[i], z_interval));
    }
  }
  out.biased_count = out.biased.size();
  std::sort(out.biased.begin(), out.biased.end(), [](const BiasedTile& a, const BiasedTile& b) {
    if (a.p_value != b.p_value) return a.p_value < b.p_value;
    return std::abs(a.change.change) > std::abs(b.change.change);
  });
  if (out.biased.size() > kBiasedKept) out.biased.resize(kBiasedKept);
  const std::vector<TileTest> whole(tests.end() - 3, tests.end());
  for (const TileTest& t : whole) {
    out.channels[static_cast<std::size_t>(t.channel)] =
        interval(t.relative(), t.relative_error(), z_interval);
  }
  out.image = luminance_change(whole, z_interval);
  const bool all_within =
      within(out.image, thresholds.tolerance) &&
      std::all_of(out.channels.begin(), out.channels.end(),
                  [&](const RelativeChange& c) { return within(c, thresholds.tolerance); });
  if (out.biased_count > 0) out.verdict = NoisyVerdict::fail;
  else if (all_within) out.verdict = NoisyVerdict::pass;
  else project_samples(whole, thresholds, out);
}

}  // namespace

// A Monte Carlo verdict is written with the word of the image verdict it becomes, so each word is
// spelt once (compare/image_verdict.cpp) and images[].monte_carlo.verdict never differs from it.
std::string_view to_string(NoisyVerdict verdict) { return to_string(to_image_verdict(verdict)); }

std::optional<NoisyVerdict> parse_noisy_verdict(std::string_view word) {
  for (const NoisyVerdict verdict :
       {NoisyVerdict::pass, NoisyVerdict::fail, NoisyVerdict::inconclusive}) {
    if (to_string(verdict) == word) return verdict;
  }
  return std::nullopt;
}

double two_sided_p(double z) { return std::erfc(std::abs(z) / std::sqrt(2.0)); }

NoisyComparison compare_noisy(const NoisyImageStats& actual, const NoisyImageStats& expected,
                              const NoisyThresholds& thresholds) {
  NoisyComparison out;
  out.tolerance = thresholds.tolerance;
  out.confidence = thresholds.confidence();
  out.width = actual.width;
  out.height = actual.height;
  out.actual_runs = actual.runs;
  out.expected_runs = expected.runs;
  if (actual.width != expected.width || actual.height != expected.height) {
    out.size_mismatch = std::to_string(actual.width) + "x" + std::to_string(actual.height) +
                        " against " + std::to_string(expected.width) + "x" +
                        std::to_string(expected.height);
    out.verdict = NoisyVerdict::fail;
    return out;
  }
  if (actual.runs < thresholds.min_runs || expected.runs < thresholds.min_runs) {
    out.why_inconclusive = "each side needs at least " + std::to_string(thresholds.min_runs) +
                           " runs to measure its noise";
    out.runs_needed = thresholds.min_runs;
    return out;  // inconclusive
  }
  std::size_t scales = 0;
  const std::vector<TileTest> tests = image_tests(actual, expected, thresholds, scales);
  out.tests = tests.size();
  judge(tests, thresholds, out);
  out.scales = scale_reports(tests, scales, thresholds);
  if (out.verdict == NoisyVerdict::pass) out.samples_factor = 1.0;
  return out;
}

}  // namespace raygate

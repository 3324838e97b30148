// The Monte Carlo image verdict on synthetic noisy renders: every run is an expected image times
// gamma-distributed noise of mean 1 (a skewed, path-tracer-like pixel error), drawn from a fixed
// seed so each test sees the same numbers every time. Different seeds of the same expected image
// must pass at the stated false-alarm rate; a 3% global dimming and a 10% change in a small
// region must fail, saying where and by how much; too few samples must be inconclusive.
#include "compare/noisy_image_compare.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>

#include "measure/probability.h"

namespace raygate {
namespace {

constexpr int kSize = 48;

// An expected image with structure: a horizontal gradient, a bright disc and a dark corner.
RgbImage expected_image(int size = kSize) {
  RgbImage image{size, size, {}};
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double dx = x - size * 0.6, dy = y - size * 0.4;
      double v = 0.2 + 0.5 * x / size + (dx * dx + dy * dy < size * size / 16.0 ? 0.6 : 0.0);
      if (x < size / 6 && y > size * 5 / 6) v = 0.01;
      image.rgb.insert(image.rgb.end(), {static_cast<float>(v), static_cast<float>(0.8 * v),
                                         static_cast<float>(0.6 * v)});
    }
  }
  return image;
}

// One run: every value times an independent Gamma(k, 1/k) factor (mean 1, relative sd 1/sqrt(k)).
RgbImage noisy_run(const RgbImage& truth, double relative_sd, std::mt19937_64& rng) {
  const double shape = 1 / (relative_sd * relative_sd);
  std::gamma_distribution<double> noise(shape, 1 / shape);
  RgbImage run = truth;
  for (float& v : run.rgb) v = static_cast<float>(v * noise(rng));
  return run;
}

NoisyImageStats runs_of(const RgbImage& truth, int runs, double relative_sd, std::mt19937_64& rng) {
  NoisyStatsBuilder builder(truth.width, truth.height, {8, 32, 128});
  for (int i = 0; i < runs; ++i) builder.add(noisy_run(truth, relative_sd, rng));
  return builder.finish();
}

RgbImage scaled(RgbImage image, double factor, TileRect where) {
  for (int y = where.y; y < where.y + where.height; ++y) {
    for (int x = where.x; x < where.x + where.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        float& v = image.rgb[(static_cast<std::size_t>(y) * image.width + x) * 3 + c];
        v = static_cast<float>(v * factor);
      }
    }
  }
  return image;
}

// Only the test proper guards (alpha): no tile minimum effect, and a tolerance so small that
// the whole image's test against it is a test against no change at all.
NoisyThresholds without_min_effect(double alpha) {
  NoisyThresholds t;
  t.alpha = alpha;
  t.tolerance = 1e-9;
  for (TileScale& s : t.tiles) s.tolerance_multiple = 0;
  return t;
}

// Statistics of a flat image, built directly: every pixel and channel `mean`, the per-pixel
// variance `variance`, `runs` runs, no inflation. What a comparison sees is then exactly known.
NoisyImageStats flat_stats(int size, int runs, double mean, double variance) {
  const std::size_t values = static_cast<std::size_t>(size) * size * 3;
  return {size,
          size,
          runs,
          std::vector<float>(values, static_cast<float>(mean)),
          std::vector<float>(values, static_cast<float>(variance)),
          {}};
}

TEST(NoisyImageCompare, NormalHelpersMatchTables) {
  EXPECT_NEAR(normal_quantile(0.975), 1.959964, 1e-5);
  EXPECT_NEAR(normal_quantile(0.5), 0.0, 1e-9);
  EXPECT_NEAR(two_sided_p(1.959964), 0.05, 1e-6);
  EXPECT_NEAR(two_sided_p(-3.0), 0.0026998, 1e-6);
}

// The test proper (no minimum effect, so only alpha guards): 300 pairs of 8 runs each with
// different seeds. A family-wise rate of 5% allows about 15 false alarms; the binomial's 99.9%
// bound is 27. An estimator that forgot a factor (the runs, the tile's pixels) fails far more.
TEST(NoisyImageCompare, DifferentSeedsOfTheSameImageFailAtMostAlphaOfTheTime) {
  std::mt19937_64 rng(20261126);
  const RgbImage truth = expected_image();
  const NoisyThresholds thresholds = without_min_effect(0.05);
  int false_alarms = 0;
  constexpr int kTrials = 300;
  for (int trial = 0; trial < kTrials; ++trial) {
    const NoisyComparison c =
        compare_noisy(runs_of(truth, 8, 0.3, rng), runs_of(truth, 8, 0.3, rng), thresholds);
    if (c.verdict == NoisyVerdict::fail) ++false_alarms;
  }
  std::printf("alpha 0.05, no minimum effect: %d false alarms in %d trials\n", false_alarms,
              kTrials);
  EXPECT_LE(false_alarms, 27) << "of " << kTrials;
}

// With the default thresholds, the same image with other seeds never fails, and with enough
// samples (32 runs a side) passes: its change is shown within the 1% tolerance. (At 16 runs a
// side the equivalence test's power is only about 90%: ErrorRatesBySimulation.)
TEST(NoisyImageCompare, AnAAComparisonWithEnoughSamplesPasses) {
  std::mt19937_64 rng(7);
  const RgbImage truth = expected_image();
  int passed = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const NoisyComparison c =
        compare_noisy(runs_of(truth, 32, 0.3, rng), runs_of(truth, 32, 0.3, rng), {});
    ASSERT_NE(c.verdict, NoisyVerdict::fail) << summarize(c);
    if (c.verdict != NoisyVerdict::pass) continue;
    ++passed;
    EXPECT_EQ(summarize(c).rfind("pass (within the ±1% image tolerance): image mean ", 0), 0u)
        << summarize(c);
  }
  std::printf("A/A, 32 runs a side of 48x48 at relative noise 0.3: %d of 50 pass\n", passed);
  EXPECT_GE(passed, 48);
}

// Too few samples for the tolerance is inconclusive, never a pass: 3 runs a side at relative
// noise 0.3 cannot show a 1% tolerance, and the line says about how many runs would.
TEST(NoisyImageCompare, AnAAComparisonWithTooFewSamplesIsInconclusive) {
  std::mt19937_64 rng(8);
  const RgbImage truth = expected_image();
  const NoisyComparison c =
      compare_noisy(runs_of(truth, 3, 0.6, rng), runs_of(truth, 3, 0.6, rng), {});
  ASSERT_EQ(c.verdict, NoisyVerdict::inconclusive) << summarize(c);
  EXPECT_GT(c.samples_factor, 1.0);
  EXPECT_GT(c.runs_needed, 3);
  EXPECT_NE(summarize(c).find("would decide it, e.g. "), std::string::npos) << summarize(c);
}

TEST(NoisyImageCompare, AThreePercentDimmerImageFails) {
  std::mt19937_64 rng(11);
  const RgbImage truth = expected_image();
  const RgbImage dimmer = scaled(truth, 0.97, {0, 0, kSize, kSize});
  for (int trial = 0; trial < 20; ++trial) {
    const NoisyComparison c =
        compare_noisy(runs_of(dimmer, 8, 0.3, rng), runs_of(truth, 8, 0.3, rng), {});
    ASSERT_EQ(c.verdict, NoisyVerdict::fail) << summarize(c);
    EXPECT_NEAR(c.image.change, -0.03, 0.01);
    EXPECT_LT(c.image.high, -0.01);  // shown beyond the tolerance
    EXPECT_EQ(summarize(c).rfind("fail (", 0), 0u) << summarize(c);
  }
}

// The words of a whole-image failure name no tile rectangle.
TEST(NoisyImageCompare, AWholeImageFailureSaysSo) {
  std::mt19937_64 rng(37);
  const RgbImage truth = expected_image();
  const RgbImage dimmer = scaled(truth, 0.97, {0, 0, kSize, kSize});
  const NoisyComparison c =
      compare_noisy(runs_of(dimmer, 16, 0.05, rng), runs_of(truth, 16, 0.05, rng), {});
  ASSERT_EQ(c.verdict, NoisyVerdict::fail);
  const std::string text = summarize(c);
  EXPECT_EQ(text.rfind("fail (beyond the ±1% image tolerance): the whole image ", 0), 0u) << text;
  EXPECT_NE(text.find("image mean -3.0"), std::string::npos) << text;
  EXPECT_NE(text.find("; 16 vs 16 runs"), std::string::npos) << text;
}

// 10% brighter in a 8x8 region at (16,24): 2.8% of the pixels. The worst tile must be inside or
// around it, and the change found about +10%.
TEST(NoisyImageCompare, ATenPercentChangeInASmallRegionFailsThere) {
  std::mt19937_64 rng(13);
  const RgbImage truth = expected_image();
  const TileRect region{16, 24, 8, 8};
  const RgbImage changed = scaled(truth, 1.10, region);
  int found = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const NoisyComparison c =
        compare_noisy(runs_of(changed, 8, 0.3, rng), runs_of(truth, 8, 0.3, rng), {});
    if (c.verdict != NoisyVerdict::fail) continue;
    ++found;
    const BiasedTile& worst = c.biased.front();
    EXPECT_LE(worst.rect.x, region.x) << summarize(c);
    EXPECT_GE(worst.rect.x + worst.rect.width, region.x + region.width);
    EXPECT_LE(worst.rect.y, region.y);
    EXPECT_GE(worst.rect.y + worst.rect.height, region.y + region.height);
    EXPECT_GT(worst.change.change, 0.0);
    // The worst of many tiles overstates its change a little (the winner's curse).
    if (worst.tile_px == 8) {
      EXPECT_GT(worst.change.change, 0.05);
      EXPECT_LT(worst.change.change, 0.25);
    }
    EXPECT_LT(std::abs(c.image.change), 0.01);  // the image as a whole hardly changed
    EXPECT_NE(summarize(c).find(" tile at ("), std::string::npos) << summarize(c);
  }
  std::printf("10%% in an 8x8 region of 48x48: found in %d of 20\n", found);
  EXPECT_GE(found, 19);
}

TEST(NoisyImageCompare, TooFewSamplesIsInconclusiveAndSaysHowManyMore) {
  std::mt19937_64 rng(17);
  const RgbImage truth = expected_image();
  const NoisyComparison c =
      compare_noisy(runs_of(truth, 3, 3.0, rng), runs_of(truth, 3, 3.0, rng), {});
  ASSERT_EQ(c.verdict, NoisyVerdict::inconclusive) << summarize(c);
  EXPECT_GT(c.samples_factor, 1.5);
  EXPECT_EQ(summarize(c).rfind("inconclusive (", 0), 0u) << summarize(c);
  EXPECT_NE(summarize(c).find("x the samples would decide it"), std::string::npos) << summarize(c);
}

TEST(NoisyImageCompare, OneRunASideCannotMeasureItsNoise) {
  std::mt19937_64 rng(19);
  const RgbImage truth = expected_image();
  const NoisyComparison c =
      compare_noisy(runs_of(truth, 1, 0.3, rng), runs_of(truth, 8, 0.3, rng), {});
  EXPECT_EQ(c.verdict, NoisyVerdict::inconclusive);
  EXPECT_NE(summarize(c).find("at least 2"), std::string::npos) << summarize(c);
}

// A real but tiny bias (0.5% everywhere) found with very many samples is within the 1%
// tolerance: a pass. Without the tolerance it would fail.
TEST(NoisyImageCompare, ATinyBiasBelowTheMinimumEffectPasses) {
  std::mt19937_64 rng(23);
  const RgbImage truth = expected_image();
  const RgbImage slightly = scaled(truth, 1.005, {0, 0, kSize, kSize});
  const NoisyImageStats a = runs_of(slightly, 16, 0.02, rng);
  const NoisyImageStats b = runs_of(truth, 16, 0.02, rng);
  EXPECT_EQ(compare_noisy(a, b, {}).verdict, NoisyVerdict::pass)
      << summarize(compare_noisy(a, b, {}));
  EXPECT_EQ(compare_noisy(a, b, without_min_effect(0.01)).verdict, NoisyVerdict::fail);
}

// Noise shared by 4x4 pixel blocks (a sampler that correlates neighbours): the tile means vary
// 16 times more than independent pixels would. The inflation measured from the runs says so,
// and the false alarms stay within alpha.
TEST(NoisyImageCompare, CorrelatedPixelNoiseIsMeasuredNotIgnored) {
  std::mt19937_64 rng(29);
  const RgbImage truth = expected_image();
  std::normal_distribution<double> normal(0, 0.1);
  auto blocky_runs = [&](int runs) {
    NoisyStatsBuilder builder(kSize, kSize, {8, 32, 128});
    for (int r = 0; r < runs; ++r) {
      RgbImage run = truth;
      for (int by = 0; by < kSize; by += 4) {
        for (int bx = 0; bx < kSize; bx += 4) {
          const double factor = 1 + normal(rng);
          run = scaled(run, factor, {bx, by, 4, 4});
        }
      }
      builder.add(run);
    }
    return builder.finish();
  };
  const NoisyImageStats first = blocky_runs(8);
  EXPECT_GT(first.inflation_for(8), 8.0);
  EXPECT_LT(first.inflation_for(8), 30.0);
  int false_alarms = 0;
  for (int trial = 0; trial < 40; ++trial) {
    if (compare_noisy(blocky_runs(8), blocky_runs(8), without_min_effect(0.05)).verdict ==
        NoisyVerdict::fail) {
      ++false_alarms;
    }
  }
  EXPECT_LE(false_alarms, 7);  // 5% of 40 is 2; 7 is the binomial's 99.9% bound
}

TEST(NoisyImageCompare, ImagesOfDifferentSizesFail) {
  std::mt19937_64 rng(31);
  const NoisyComparison c = compare_noisy(runs_of(expected_image(48), 4, 0.3, rng),
                                          runs_of(expected_image(32), 4, 0.3, rng), {});
  EXPECT_EQ(c.verdict, NoisyVerdict::fail);
  EXPECT_EQ(summarize(c), "fail (size 48x48 against 32x32)");
}

TEST(NoisyImageCompare, TileGridCoversTheImageOnce) {
  const std::vector<TileRect> grid = tile_grid(20, 10, 8);
  ASSERT_EQ(grid.size(), 6u);
  EXPECT_EQ(grid.back(), (TileRect{16, 8, 4, 2}));
  EXPECT_EQ(tile_scales(48, 48, {8, 32, 128}), (std::vector<int>{8, 32, kWholeImage}));
}

// The case (Blender Cycles gears, about 30 runs a side): image mean -2.03% with a 95%
// interval of [-3.42%, -0.64%]. It excludes zero but reaches inside the 1% tolerance: neither
// shown within it nor beyond it, so inconclusive, never "same within noise". With ten times the
// runs the same change is shown beyond the tolerance and fails.
TEST(NoisyImageCompare, TheGearsCaseIsInconclusiveNotAPass) {
  constexpr int kRuns = 30;
  // Per side: relative standard error sqrt(v / (pixels x runs)) / mean = 0.709% / sqrt(2).
  const double variance = 0.4343;
  const NoisyComparison c = compare_noisy(flat_stats(48, kRuns, 0.5 * (1 - 0.0203), variance),
                                          flat_stats(48, kRuns, 0.5, variance), {});
  EXPECT_EQ(c.verdict, NoisyVerdict::inconclusive) << summarize(c);
  EXPECT_NEAR(c.image.change, -0.0203, 1e-4);
  const double half_95 =
      (c.image.high - c.image.low) / 2 / normal_quantile(0.95) * normal_quantile(0.975);
  EXPECT_NEAR(c.image.change - half_95, -0.0342, 3e-4);
  EXPECT_NEAR(c.image.change + half_95, -0.0064, 3e-4);
  EXPECT_LT(c.image.low, -0.01);   // reaches beyond the tolerance...
  EXPECT_GT(c.image.high, -0.01);  // ...and inside it
  EXPECT_GT(c.samples_factor, 1.0);
  EXPECT_EQ(summarize(c).rfind("inconclusive (", 0), 0u) << summarize(c);
  EXPECT_NE(summarize(c).find("±1% image tolerance"), std::string::npos) << summarize(c);
  const NoisyComparison more =
      compare_noisy(flat_stats(48, 10 * kRuns, 0.5 * (1 - 0.0203), variance),
                    flat_stats(48, 10 * kRuns, 0.5, variance), {});
  EXPECT_EQ(more.verdict, NoisyVerdict::fail) << summarize(more);
  EXPECT_LT(more.image.high, -0.01);
}

// Per pixel and channel a mean drawn as the mean of `runs` runs of variance `variance` would
// be (normal), around `truth` times `factor[channel]`: the sufficient statistics of a render,
// without rendering, so thousands of comparisons take seconds.
NoisyImageStats sampled_stats(const RgbImage& truth, int runs, double relative_sd,
                              const std::array<double, 3>& factor, std::mt19937_64& rng) {
  NoisyImageStats stats{truth.width, truth.height, runs, truth.rgb, truth.rgb, {}};
  std::normal_distribution<double> normal(0.0, 1.0);
  for (std::size_t i = 0; i < stats.mean.size(); ++i) {
    const double value = truth.rgb[i] * factor[i % 3];
    const double sd = relative_sd * truth.rgb[i];
    stats.mean[i] = static_cast<float>(value + normal(rng) * sd / std::sqrt(runs));
    stats.variance[i] = static_cast<float>(sd * sd);
  }
  return stats;
}

// Whatever the change, noise and runs, no comparison passes while an interval it reports
// (the luminance mean's or a channel's) reaches beyond the tolerance.
TEST(NoisyImageCompare, NoPassWhileAnIntervalReachesBeyondTheTolerance) {
  std::mt19937_64 rng(61);
  const RgbImage truth = expected_image(32);
  std::uniform_real_distribution<double> change(-0.03, 0.03), noise(0.05, 1.0),
      tolerance(0.005, 0.03);
  std::uniform_int_distribution<int> runs(2, 40);
  int passes = 0;
  for (int trial = 0; trial < 1500; ++trial) {
    NoisyThresholds thresholds;
    thresholds.tolerance = tolerance(rng);
    const double sd = noise(rng);
    const NoisyComparison c =
        compare_noisy(sampled_stats(truth, runs(rng), sd,
                                    {1 + change(rng), 1 + change(rng), 1 + change(rng)}, rng),
                      sampled_stats(truth, runs(rng), sd, {1, 1, 1}, rng), thresholds);
    if (c.verdict != NoisyVerdict::pass) continue;
    ++passes;
    for (const RelativeChange& i : {c.image, c.channels[0], c.channels[1], c.channels[2]}) {
      ASSERT_GE(i.low, -thresholds.tolerance) << summarize(c);
      ASSERT_LE(i.high, thresholds.tolerance) << summarize(c);
    }
  }
  std::printf("%d of 1500 random comparisons passed, each inside its tolerance\n", passes);
  EXPECT_GT(passes, 100);  // the property was tested on passes, not vacuously
}

// The error rates by simulation (one comparison per trial, 48x48, 16 runs a side, relative
// noise 0.3 per pixel): an unchanged image fails at most alpha of the time and passes almost
// always; a change of exactly the tolerance in one channel passes at most about
// equivalence_alpha (5%) of the time; a change of twice the tolerance fails almost always.
TEST(NoisyImageCompare, ErrorRatesBySimulation) {
  std::mt19937_64 rng(67);
  const RgbImage truth = expected_image();
  constexpr int kTrials = 400;
  auto rates = [&](const std::array<double, 3>& factor, int runs, double sd) {
    std::array<int, 3> counts{};  // pass, fail, inconclusive
    for (int trial = 0; trial < kTrials; ++trial) {
      const NoisyComparison c = compare_noisy(sampled_stats(truth, runs, sd, factor, rng),
                                              sampled_stats(truth, runs, sd, {1, 1, 1}, rng), {});
      ++counts[static_cast<std::size_t>(c.verdict)];
    }
    return counts;
  };
  const auto same = rates({1, 1, 1}, 16, 0.3);
  const auto at_tolerance = rates({1.01, 1, 1}, 16, 0.3);
  const auto twice = rates({0.98, 0.98, 0.98}, 16, 0.3);
  std::printf(
      "of %d: unchanged pass %d fail %d inconclusive %d; R +1%% (the tolerance) pass %d "
      "fail %d inconclusive %d; -2%% pass %d fail %d inconclusive %d\n",
      kTrials, same[0], same[1], same[2], at_tolerance[0], at_tolerance[1], at_tolerance[2],
      twice[0], twice[1], twice[2]);
  EXPECT_LE(same[1], 10);  // alpha 1%: 4 expected; 10 is the binomial's 99.9% bound
  // The equivalence test's power at this sample size: about 92% (370 of 400 when written); an
  // unchanged image that does not pass is inconclusive, and a compare gives it more runs.
  EXPECT_GE(same[0], kTrials * 85 / 100);
  EXPECT_LE(at_tolerance[0], 34);  // equivalence_alpha 5%: 20 expected; 99.9% bound 34
  EXPECT_GE(twice[1], kTrials * 95 / 100);
  EXPECT_EQ(twice[0], 0);
}

}  // namespace
}  // namespace raygate

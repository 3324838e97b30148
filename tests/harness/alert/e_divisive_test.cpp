// E-divisive means on synthetic series: a flat series has no change point, a step has one at
// the step, two steps two; the permutation test is seeded (same series, same answer) and never
// reports a p-value below 1 / (permutations + 1).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "alert/e_divisive.h"

namespace raygate {
namespace {

// ±1% of deterministic, irregular noise around `level`.
double noisy(double level, std::size_t i) {
  return level * (1.0 + 0.01 * std::sin(2.399 * static_cast<double>(i) + 0.7));
}

std::vector<double> series(std::size_t n,
                           const std::vector<std::pair<std::size_t, double>>& levels) {
  std::vector<double> values;
  for (std::size_t i = 0; i < n; ++i) {
    double level = 1.0;
    for (const auto& [from, value] : levels) {
      if (i >= from) level = value;
    }
    values.push_back(noisy(level, i));
  }
  return values;
}

TEST(EDivisive, FlatNoisySeriesHasNoChangePoint) {
  EXPECT_TRUE(e_divisive(series(15, {})).empty());
  EXPECT_TRUE(e_divisive(series(40, {})).empty());
}

TEST(EDivisive, ConstantSeriesHasNoChangePoint) {
  EXPECT_TRUE(e_divisive(std::vector<double>(20, 0.8)).empty());
}

TEST(EDivisive, TenPercentStepIsFoundAtTheStep) {
  // 15 commits, the 9th (index 8) 10% slower and every one after it.
  const std::vector<double> values = series(15, {{8, 1.1}});
  const std::vector<ChangePoint> found = e_divisive(values);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].index, 8u);
  EXPECT_NEAR(found[0].relative_change(), 0.10, 0.01);
  EXPECT_LT(found[0].p_value, 0.05);
  EXPECT_GT(found[0].statistic, 0.0);
}

TEST(EDivisive, ImprovementIsAChangePointToo) {
  const std::vector<ChangePoint> found = e_divisive(series(15, {{6, 0.85}}));
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].index, 6u);
  EXPECT_NEAR(found[0].relative_change(), -0.15, 0.01);
}

TEST(EDivisive, TwoStepsGiveTwoChangePointsWithTheirSegmentsMeans) {
  const std::vector<ChangePoint> found = e_divisive(series(30, {{10, 1.2}, {20, 1.0}}));
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].index, 10u);
  EXPECT_EQ(found[1].index, 20u);
  EXPECT_NEAR(found[0].mean_before, 1.0, 0.005);
  EXPECT_NEAR(found[0].mean_after, 1.2, 0.01);
  EXPECT_NEAR(found[1].mean_before, 1.2, 0.01);
  EXPECT_NEAR(found[1].mean_after, 1.0, 0.005);
}

TEST(EDivisive, StepNearerTheEndThanMinSegmentIsNotPlacedThere) {
  // Two points after the change: with three needed on each side it cannot be placed at 13.
  for (const ChangePoint& found : e_divisive(series(15, {{13, 1.1}}))) EXPECT_NE(found.index, 13u);
  EDivisiveOptions two;
  two.min_segment = 2;
  const std::vector<ChangePoint> found = e_divisive(series(15, {{13, 1.3}}), two);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_EQ(found[0].index, 13u);
}

TEST(EDivisive, SameSeedSameAnswerAndPValueFloor) {
  const std::vector<double> values = series(15, {{8, 1.1}});
  EDivisiveOptions options;
  options.permutations = 99;
  const std::vector<ChangePoint> a = e_divisive(values, options);
  const std::vector<ChangePoint> b = e_divisive(values, options);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(a[0].p_value, b[0].p_value);
  EXPECT_GE(a[0].p_value, 1.0 / 100.0);
}

TEST(EDivisive, TooFewPermutationsCannotReachSignificance) {
  EDivisiveOptions options;
  options.permutations = 9;  // p >= 0.1 whatever the data
  EXPECT_TRUE(e_divisive(series(15, {{8, 1.5}}), options).empty());
}

TEST(EDivisive, BestSplitOfAShortSegmentIsNone) {
  const std::vector<double> values{1.0, 2.0, 3.0, 4.0, 5.0};
  EXPECT_EQ(best_split(values, 0, 5, 3).index, 0u);
  const Split split = best_split(std::vector<double>{1, 1, 1, 2, 2, 2}, 0, 6, 3);
  EXPECT_EQ(split.index, 3u);
}

TEST(EDivisive, StatisticMatchesTheDefinitionOnASmallCase) {
  // {0, 0 | 1, 1}: between-mean distance 1, within 0: Q = (2 * 2 / 4) * (2 * 1 - 0 - 0) = 2.
  const Split split = best_split(std::vector<double>{0, 0, 1, 1}, 0, 4, 2);
  EXPECT_EQ(split.index, 2u);
  EXPECT_DOUBLE_EQ(split.statistic, 2.0);
}

}  // namespace
}  // namespace raygate

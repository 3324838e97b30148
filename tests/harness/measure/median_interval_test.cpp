// The order-statistic interval for a median: its ranks against binomial tables, its coverage on
// skewed noise at the small round counts a gate decides on, and that it refuses too few values.
#include "measure/median_interval.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "measure/change.h"
#include "measure/confidence_sequence.h"
#include "measure/probability.h"
#include "measure/random.h"

namespace raygate {
namespace {

TEST(MedianInterval, FewestValuesForEachConfidence) {
  // 2 * 0.5^n <= 1 - c: n = 6 for 95% (2/64 = 3.1%), 8 for 99% (2/256 = 0.8%), 4 for 80%.
  EXPECT_EQ(min_values_for_median_interval(0.95), 6u);
  EXPECT_EQ(min_values_for_median_interval(0.99), 8u);
  EXPECT_EQ(min_values_for_median_interval(0.80), 4u);
  EXPECT_THROW(min_values_for_median_interval(1.0), std::invalid_argument);
  EXPECT_THROW(min_values_for_median_interval(0.0), std::invalid_argument);
}

// The shared check (measure/probability.h) names the parameter and its open range, and a NaN
// level is as far outside it as 1 is.
TEST(MedianInterval, ALevelOutsideItsRangeIsRefusedByName) {
  const auto message = [](auto call) {
    try {
      call();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("(no throw)");
  };
  EXPECT_EQ(message([] { (void)min_values_for_median_interval(1.0); }),
            "median interval: confidence must lie in (0, 1)");
  EXPECT_EQ(message([] { (void)min_values_for_median_interval(std::nan("")); }),
            "median interval: confidence must lie in (0, 1)");
  EXPECT_EQ(message([] {
              (void)median_sequence_interval(std::vector<double>{1, 2, 3}, 0.5);
            }),
            "confidence sequence: alpha per side must lie in (0, 0.5)");
}

TEST(MedianInterval, LogChooseMatchesSmallBinomialCoefficients) {
  EXPECT_NEAR(std::exp(log_choose(10, 3)), 120.0, 1e-9);
  EXPECT_NEAR(std::exp(log_choose(7, 0)), 1.0, 1e-12);
  EXPECT_NEAR(std::exp(log_choose(7, 7)), 1.0, 1e-12);
  // Where 1000! overflows a double, its logarithm does not: ln C(1000, 500) ~ 689.47.
  EXPECT_NEAR(log_choose(1000, 500), 689.4672, 1e-3);
}

TEST(MedianInterval, RanksMatchTheBinomialTable) {
  std::vector<double> values;
  for (int i = 1; i <= 30; ++i) values.push_back(i);  // x(i) = i
  auto ranks = [&](std::size_t n) {
    const auto interval = median_interval(std::span(values).first(n), 0.95);
    return interval ? std::pair<double, double>{interval->lower, interval->upper}
                    : std::pair<double, double>{0, 0};
  };
  // Published 95% ranks for the median: n=6 (1,6), n=10 (2,9), n=20 (6,15), n=30 (10,21).
  EXPECT_EQ(ranks(6), (std::pair<double, double>{1, 6}));
  EXPECT_EQ(ranks(10), (std::pair<double, double>{2, 9}));
  EXPECT_EQ(ranks(20), (std::pair<double, double>{6, 15}));
  EXPECT_EQ(ranks(30), (std::pair<double, double>{10, 21}));
  EXPECT_FALSE(median_interval(std::span(values).first(5), 0.95));
}

TEST(MedianInterval, OrderOfValuesDoesNotMatter) {
  const std::vector<double> values{5, 1, 4, 2, 6, 3, 0.5};
  const auto interval = median_interval(values, 0.95);
  ASSERT_TRUE(interval);
  EXPECT_DOUBLE_EQ(interval->lower, 0.5);
  EXPECT_DOUBLE_EQ(interval->upper, 6);
}

TEST(MedianInterval, CoversTheMedianOfSkewedNoiseAtLeastNominally) {
  // Timing noise is one-sided: mostly small, sometimes a large spike. Exponential noise has
  // median ln 2; count how often the interval of n draws covers it.
  Xoshiro256 rng(11);
  for (const std::size_t n : {6u, 9u, 15u}) {
    int covered = 0;
    const int trials = 4000;
    for (int t = 0; t < trials; ++t) {
      std::vector<double> draws;
      for (std::size_t i = 0; i < n; ++i) draws.push_back(-std::log(1.0 - rng.uniform_unit()));
      if (median_interval(draws, 0.95)->contains(std::log(2.0))) ++covered;
    }
    EXPECT_GE(covered, 0.95 * trials - 40) << n << " values";  // 40: ~3 standard errors
  }
}

TEST(MedianInterval, NoChangeVerdictBeforeTheIntervalExists) {
  // Five rounds, each head exactly 10% slower: the numbers are clear, but five paired rounds
  // cannot give a 95% interval for the median, so the verdict waits for the sixth.
  std::vector<CompareRound> rounds(5, CompareRound{1.0, 1.0, 1.1});
  EXPECT_EQ(classify_change(summarize_change(rounds)), ChangeVerdict::inconclusive);
  rounds.push_back({1.0, 1.0, 1.1});
  EXPECT_EQ(classify_change(summarize_change(rounds)), ChangeVerdict::regressed);
}

TEST(MedianInterval, OneSpikeInThreeRoundsIsNotARegression) {
  // The false alarm bench/gate-reliability caught: an unchanged commit, rounds +0.2%, +6.4%,
  // +39.7% (one run hit by another process). A bootstrap "95%" interval of three values is
  // their range, which excluded 0; now three rounds decide nothing.
  const std::vector<CompareRound> rounds{
      {0.13, 0.1627, 0.1631}, {0.13, 0.1745, 0.1857}, {0.13, 0.1671, 0.2334}};
  EXPECT_EQ(classify_change(summarize_change(rounds)), ChangeVerdict::inconclusive);
}

}  // namespace
}  // namespace raygate

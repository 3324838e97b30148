// Descriptive statistics on samples small enough to check by hand, and the PRNG against an
// independent implementation (so a CI computed here equals one computed anywhere else).
#include "measure/descriptive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "measure/random.h"

namespace raygate {
namespace {

TEST(MeasureDescriptive, MedianOddEvenAndUnsorted) {
  EXPECT_DOUBLE_EQ(median(std::vector<double>{3, 1, 2}), 2.0);
  EXPECT_DOUBLE_EQ(median(std::vector<double>{4, 1, 3, 2}), 2.5);
  EXPECT_DOUBLE_EQ(median(std::vector<double>{7}), 7.0);
}

TEST(MeasureDescriptive, MedianLeavesInputAlone) {
  const std::vector<double> values{5, 1, 4};
  EXPECT_DOUBLE_EQ(median(values), 4.0);
  EXPECT_EQ(values, (std::vector<double>{5, 1, 4}));
}

TEST(MeasureDescriptive, QuantileIsDefinitionSeven) {
  const std::vector<double> values{10, 9, 8, 7, 6, 5, 4, 3, 2, 1};
  EXPECT_DOUBLE_EQ(quantile(values, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile(values, 1.0), 10.0);
  EXPECT_DOUBLE_EQ(quantile(values, 0.25), 3.25);  // h = 2.25
  EXPECT_DOUBLE_EQ(quantile(values, 0.5), 5.5);
  EXPECT_DOUBLE_EQ(quantile(values, 0.9), 9.1);  // h = 8.1
  EXPECT_THROW(quantile(values, 1.5), std::invalid_argument);
}

TEST(MeasureDescriptive, MadRawAndScaled) {
  // median 2; |x - 2| = {1,1,0,0,2,4,7}; their median is 1.
  const std::vector<double> values{1, 1, 2, 2, 4, 6, 9};
  EXPECT_DOUBLE_EQ(mad_raw(values), 1.0);
  EXPECT_DOUBLE_EQ(mad_scaled(values), kMadNormalScale);
  EXPECT_DOUBLE_EQ(mad_raw(std::vector<double>{3, 3, 3}), 0.0);
}

TEST(MeasureDescriptive, MeanDeviationVariation) {
  const std::vector<double> values{2, 4, 4, 4, 5, 5, 7, 9};
  EXPECT_DOUBLE_EQ(mean(values), 5.0);
  EXPECT_DOUBLE_EQ(standard_deviation(values), std::sqrt(32.0 / 7.0));
  EXPECT_DOUBLE_EQ(coefficient_of_variation(values), std::sqrt(32.0 / 7.0) / 5.0);
  EXPECT_DOUBLE_EQ(standard_deviation(std::vector<double>{42}), 0.0);
}

TEST(MeasureDescriptive, GeometricMean) {
  EXPECT_NEAR(geometric_mean(std::vector<double>{1, 2, 4, 8}), std::sqrt(8.0), 1e-12);
  EXPECT_THROW(geometric_mean(std::vector<double>{1, 0}), std::invalid_argument);
}

TEST(MeasureDescriptive, EmptySampleThrows) {
  const std::vector<double> empty;
  EXPECT_THROW(median(empty), std::invalid_argument);
  EXPECT_THROW(mad_raw(empty), std::invalid_argument);
  EXPECT_THROW(mean(empty), std::invalid_argument);
}

TEST(MeasureRandom, SplitmixReferenceValue) {
  std::uint64_t state = 0;
  EXPECT_EQ(splitmix64_next(state), 0xe220a8397b1dcdafULL);  // published first output for seed 0
}

TEST(MeasureRandom, MatchesIndependentImplementation) {
  // Values from a separate Python implementation of the same algorithms.
  Xoshiro256 rng(0x7261796761746531ULL);
  EXPECT_EQ(rng.next(), 0x0a2209624479fcbdULL);
  EXPECT_EQ(rng.next(), 0xb81023c73a3979b5ULL);
  EXPECT_EQ(rng.next(), 0x7226be5546ad7c44ULL);
  Xoshiro256 small(1);
  const std::vector<std::uint64_t> expected{7, 2, 0, 3, 1, 2, 6, 9, 1, 8};
  for (std::uint64_t want : expected) EXPECT_EQ(small.uniform_below(10), want);
}

TEST(MeasureRandom, UniformBelowStaysInRangeAndCoversIt) {
  Xoshiro256 rng(99);
  std::vector<int> hits(7, 0);
  for (int i = 0; i < 7000; ++i) ++hits[rng.uniform_below(7)];
  for (int count : hits) EXPECT_NEAR(count, 1000, 150);
  EXPECT_THROW(rng.uniform_below(0), std::invalid_argument);
  for (int i = 0; i < 1000; ++i) {
    const double u = rng.uniform_unit();
    EXPECT_GE(u, 0.0);
    EXPECT_LT(u, 1.0);
  }
}

}  // namespace
}  // namespace raygate

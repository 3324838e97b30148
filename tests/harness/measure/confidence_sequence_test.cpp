// The anytime-valid confidence sequence for a median: the mixture martingale against values
// worked by hand, the interval's ranks, and its error rate by simulation under the VM's noise (vm_noise.h)
// at every one of 60 looks, against the one-look interval that the old rule looked at 25 times.
#include "measure/confidence_sequence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "measure/median_interval.h"
#include "vm_noise.h"

namespace raygate {
namespace {

TEST(MeasureConfidenceSequence, WealthMatchesTheMixtureWorkedByHand) {
  // n = 1: count 0 -> 2^2 * B(1, 2) * P(Bin(2, 1/2) <= 0) = 4 * 1/2 * 1/4 = 0.5;
  //        count 1 -> 4 * B(2, 1) * P(Bin(2, 1/2) <= 1) = 4 * 1/2 * 3/4 = 1.5.
  EXPECT_NEAR(median_sequence_log_wealth(1, 0), std::log(0.5), 1e-12);
  EXPECT_NEAR(median_sequence_log_wealth(1, 1), std::log(1.5), 1e-12);
  // n = 4, count 3: 2^5 * B(4, 2) * P(Bin(5, 1/2) <= 3) = 32 * (1/20) * (26/32) = 1.3.
  EXPECT_NEAR(median_sequence_log_wealth(4, 3), std::log(1.3), 1e-12);
  // All n on one side: 2^(n+1) / (n+1) * (1 - 2^-(n+1)); n = 13: 16383 / 14.
  EXPECT_NEAR(median_sequence_log_wealth(13, 13), std::log(16383.0 / 14.0), 1e-9);
  // The wealth grows with the count (the scan for k* relies on it).
  for (std::size_t count = 1; count <= 40; ++count) {
    EXPECT_GT(median_sequence_log_wealth(40, count), median_sequence_log_wealth(40, count - 1));
  }
  EXPECT_THROW(median_sequence_log_wealth(5, 6), std::invalid_argument);
  const std::vector<double> some{1.0, 2.0};
  EXPECT_THROW(median_sequence_interval(some, 0.0), std::invalid_argument);
  EXPECT_THROW(median_sequence_interval(some, 0.5), std::invalid_argument);
}

TEST(MeasureConfidenceSequence, WiderThanOneLookAndNarrowingWithRounds) {
  // All n values on one side must reach 1 / alpha. At alpha 0.025 (40): 7 values reach 31.9, 8
  // reach 56.8. At 0.01/13 (1300): 13 values reach 1170, 14 reach 2184, three fewer than the
  // normal-mixture sequence raygate used before needed (17).
  EXPECT_EQ(min_values_for_median_sequence(0.025), 8u);
  EXPECT_EQ(min_values_for_median_sequence(0.01 / 13), 14u);
  // Below the minimum no interval; at it, the range of the values.
  std::vector<double> values;
  for (int i = 0; i < 7; ++i) values.push_back(i);
  EXPECT_FALSE(median_sequence_interval(values, 0.025).has_value());
  values.push_back(7);
  const std::optional<Interval> first = median_sequence_interval(values, 0.025);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->lower, 0.0);
  EXPECT_EQ(first->upper, 7.0);
  // 40 values 0..39 in shuffled order: the ends are the order statistics of ranks n + 1 - k*
  // and k*, k* the smallest count whose wealth reaches 1 / 0.025, and the one-look 95% interval
  // lies strictly inside.
  std::vector<double> forty;
  for (int i = 0; i < 40; ++i) forty.push_back((i * 17) % 40);
  std::size_t k_star = 0;
  while (median_sequence_log_wealth(40, k_star) < std::log(40.0)) ++k_star;
  EXPECT_EQ(k_star, 30u);  // 29 values at or below m do not reject it yet, 30 do
  const std::optional<Interval> cs = median_sequence_interval(forty, 0.025);
  ASSERT_TRUE(cs.has_value());
  EXPECT_EQ(cs->lower, static_cast<double>(40 - k_star));  // sorted values are 0..39: x(k) = k - 1
  EXPECT_EQ(cs->upper, static_cast<double>(k_star - 1));
  const std::optional<Interval> one_look = median_interval(forty, 0.95);
  EXPECT_LT(cs->lower, one_look->lower);
  EXPECT_GT(cs->upper, one_look->upper);
}

// How many of `sequences` A/A streams (true median of ln(head/base) 0) have, at some look from
// the 1st to the 60th, an interval lying wholly above 0: the error that raises a false alarm.
template <typename IntervalAt>
int false_alarms(int sequences, testing::VmNoise noise, IntervalAt interval_at) {
  int alarms = 0;
  for (int s = 0; s < sequences; ++s) {
    testing::VmRounds rounds(9000 + static_cast<std::uint64_t>(s), noise);
    std::vector<double> logs;
    for (int look = 0; look < 60; ++look) {
      const CompareRound r = rounds.next(1.0);
      logs.push_back(std::log(r.head_seconds / r.base_seconds));
      const std::optional<Interval> i = interval_at(logs);
      if (i && i->lower > 0.0) {
        ++alarms;
        break;
      }
    }
  }
  return alarms;
}

TEST(MeasureConfidenceSequence, ErrorRateUnderVmNoiseHoldsAtEveryLook) {
  // 2,000 A/A sequences of 60 rounds each under spikes and bursts; 2.5% allowed per side.
  const testing::VmNoise noise;
  const int sequence_alarms = false_alarms(2000, noise, [](const std::vector<double>& logs) {
    return median_sequence_interval(logs, 0.025);
  });
  EXPECT_LE(sequence_alarms, 50) << "confidence sequence: " << sequence_alarms << " / 2000";
  // The one-look 95% interval, looked at after every round from the 6th, crosses far more
  // often than its 2.5%: the repeated-looks problem the sequence removes.
  const int one_look_alarms = false_alarms(
      2000, noise, [](const std::vector<double>& logs) { return median_interval(logs, 0.95); });
  EXPECT_GT(one_look_alarms, 3 * 50) << "one look, 60 times: " << one_look_alarms << " / 2000";
}

TEST(MeasureConfidenceSequence, CoversASkewedMedianNotItsMean) {
  // ln-changes from a skewed law: 0.02 + spikes of +0.3 on 30% of rounds. Its median is 0.02
  // plus the Normal part's, far from its mean (+0.09): the sequence must cover the median.
  int misses = 0;
  for (int s = 0; s < 1000; ++s) {
    Xoshiro256 rng(500 + static_cast<std::uint64_t>(s));
    std::vector<double> logs;
    // The median of 0.02 + 0.02 Z + 0.3 B(0.3): solve P(X <= m) = 1/2 numerically below.
    for (int look = 0; look < 60; ++look) {
      logs.push_back(0.02 + 0.02 * testing::standard_normal(rng) +
                     (rng.uniform_unit() < 0.3 ? 0.3 : 0.0));
      const std::optional<Interval> i = median_sequence_interval(logs, 0.025);
      // P(X <= m) = 0.7 Phi((m - 0.02) / 0.02) (+ a negligible spike part) = 1/2 at
      // Phi = 0.714286, (m - 0.02) / 0.02 = 0.565949: m = 0.0313190.
      if (i && (i->lower > 0.0313190 || i->upper < 0.0313190)) {
        ++misses;
        break;
      }
    }
  }
  EXPECT_LE(misses, 50) << misses << " / 1000 sequences lost the median at some look";
}

}  // namespace
}  // namespace raygate

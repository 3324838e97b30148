// The anytime-valid confidence sequence for a median: the boundary against values worked by
// hand, the interval's ranks, and its error rate by simulation under the VM's noise (vm_noise.h)
// at every one of 60 looks, against the one-look interval that the old rule looked at 25 times.
#include "measure/confidence_sequence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "measure/median_interval.h"
#include "vm_noise.h"

namespace raygate {
namespace {

TEST(MeasureConfidenceSequence, BoundaryMatchesTheMixtureFormula) {
  // n = 20, alpha 0.025 each side, rho 1: V = 5, b^2 = 6 ln(6 / 0.0025) = 6 * 7.78322 = 46.699.
  EXPECT_NEAR(median_sequence_boundary(20, 0.025, 1.0), std::sqrt(6.0 * std::log(6.0 / 0.0025)),
              1e-12);
  EXPECT_NEAR(median_sequence_boundary(20, 0.025, 1.0), 6.83368, 1e-4);
  // rho = (24 / 4) / (2 ln 20 + ln(1 + 2 ln 20)) = 6 / (5.991465 + 1.944691) = 0.756034.
  EXPECT_NEAR(sequence_rho(0.025), 0.756034, 1e-5);
  EXPECT_THROW(median_sequence_boundary(5, 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(median_sequence_boundary(5, 0.5, 1.0), std::invalid_argument);
  EXPECT_THROW(median_sequence_boundary(5, 0.01, 0.0), std::invalid_argument);
}

TEST(MeasureConfidenceSequence, WiderThanOneLookAndNarrowingWithRounds) {
  EXPECT_EQ(min_values_for_median_sequence(0.025), 10u);
  EXPECT_EQ(min_values_for_median_sequence(0.01 / 13), 17u);
  // Below the minimum no interval; at it, the range of the values.
  std::vector<double> values;
  for (int i = 0; i < 9; ++i) values.push_back(i);
  EXPECT_FALSE(median_sequence_interval(values, 0.025).has_value());
  values.push_back(9);
  const std::optional<Interval> first = median_sequence_interval(values, 0.025);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->lower, 0.0);
  EXPECT_EQ(first->upper, 9.0);
  // 40 values 0..39 in shuffled order: the ends are the order statistics of ranks
  // floor(20 - b) + 1 and ceil(20 + b), and the one-look 95% interval lies strictly inside.
  std::vector<double> forty;
  for (int i = 0; i < 40; ++i) forty.push_back((i * 17) % 40);
  const double b = median_sequence_boundary(40, 0.025, sequence_rho(0.025));
  const long lo = static_cast<long>(std::floor(20.0 - b)) + 1;
  const long hi = static_cast<long>(std::ceil(20.0 + b));
  const std::optional<Interval> cs = median_sequence_interval(forty, 0.025);
  ASSERT_TRUE(cs.has_value());
  EXPECT_EQ(cs->lower, static_cast<double>(lo - 1));  // sorted values are 0..39: x(k) = k - 1
  EXPECT_EQ(cs->upper, static_cast<double>(hi - 1));
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
  const int one_look_alarms = false_alarms(2000, noise, [](const std::vector<double>& logs) {
    return median_interval(logs, 0.95);
  });
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

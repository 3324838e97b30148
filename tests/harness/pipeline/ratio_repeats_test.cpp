// `run`'s choice between one run and the fastest of two per round (pipeline/ratio_repeats.h).
#include "pipeline/ratio_repeats.h"

#include <gtest/gtest.h>

#include <vector>

#include "noisy_rounds.h"

namespace raygate {
namespace {

Round round_of(double baseline_seconds, double tracer_seconds, int runs_each = 1) {
  return testing::round_of(testing::kBaselineTracer, baseline_seconds, tracer_seconds, runs_each);
}

std::vector<Round> one_sided_noise(int pairs) {
  return testing::one_sided_noise(testing::kBaselineTracer, pairs);
}

// Rounds whose noise is the same in a pair's two rounds (a slow spell as long as both): the
// fastest of two is as spread as one run.
std::vector<Round> pairwise_alike(int pairs) {
  std::vector<Round> rounds;
  for (int k = 0; k < pairs; ++k) {
    const double tracer = 1.0 + 0.03 * ((k % 5) - 2);
    rounds.push_back(round_of(1.0, tracer));
    rounds.push_back(round_of(1.0, tracer));
  }
  return rounds;
}

TEST(RatioRepeats, OneRunUntilTenRoundsShowTheNoise) {
  for (int pairs = 0; pairs < 5; ++pairs) {
    EXPECT_EQ(ratio_repeats(one_sided_noise(pairs), Role::tracer), 1u) << pairs << " pairs";
  }
  EXPECT_EQ(ratio_repeats(one_sided_noise(5), Role::tracer), 2u);
}

TEST(RatioRepeats, NoiseTheFastestOfTwoDoesNotRemoveKeepsOneRun) {
  EXPECT_EQ(ratio_repeats(pairwise_alike(6), Role::tracer), 1u);
  std::vector<Round> exact(12, round_of(1.0, 2.0));
  EXPECT_EQ(ratio_repeats(exact, Role::tracer), 1u) << "rounds without spread gain nothing";
}

TEST(RatioRepeats, RepeatedRoundsJudgeThemselvesOnceThereAreTen) {
  std::vector<Round> rounds = one_sided_noise(5);
  // Nine repeated rounds as spread as one run: the pairs still speak for the fastest of two.
  for (int k = 0; k < 9; ++k) rounds.push_back(round_of(1.0, 1.0 + 0.08 * (k % 3), 2));
  EXPECT_EQ(ratio_repeats(rounds, Role::tracer), 2u);
  // The tenth: their own spread shows the fastest of two does not pay on this machine.
  rounds.push_back(round_of(1.0, 1.08, 2));
  EXPECT_EQ(ratio_repeats(rounds, Role::tracer), 1u);
}

}  // namespace
}  // namespace raygate

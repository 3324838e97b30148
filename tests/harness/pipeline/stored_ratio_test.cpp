// pipeline/stored_ratio: when a compare's stored ratio counts as precise, how many ratio rounds
// a scene may still take, and the closing line that says so.
#include "pipeline/stored_ratio.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace raygate {
namespace {

// Round with base at `base_seconds` and, when `baseline_seconds` > 0, the baseline.
Round round_of(double base_seconds, double baseline_seconds) {
  Round round;
  round.runs["base"].seconds = base_seconds;
  round.runs["head"].seconds = base_seconds;
  if (baseline_seconds > 0.0) round.runs["baseline"].seconds = baseline_seconds;
  return round;
}

RatioSummary ratio_of(const std::vector<double>& base_seconds) {
  std::vector<RoundSample> samples;
  for (const double seconds : base_seconds) samples.push_back({seconds, 1.0});
  return summarize_ratio(samples, 0.95);
}

TEST(StoredRatio, ThreeIdenticalRoundsAreNotAPreciseRatio) {
  // Three rounds make the range a 75% interval, so however narrow, they are not a 95% one.
  EXPECT_FALSE(stored_ratio_precise(ratio_of({0.5, 0.5, 0.5}), 0.95));
  EXPECT_EQ(stored_ratio_fewest_rounds(0.95), 6u);
  EXPECT_TRUE(stored_ratio_precise(ratio_of({0.5, 0.5, 0.5, 0.5, 0.5, 0.5}), 0.95));
  EXPECT_EQ(stored_ratio_fewest_rounds(0.99), 8u);
  EXPECT_FALSE(stored_ratio_precise(ratio_of({0.5, 0.5, 0.5, 0.5, 0.5, 0.5}), 0.99));
}

TEST(StoredRatio, PreciseMeansWithinTwoPercentEitherSide) {
  // Six rounds: the interval is their range, here 0.491-0.509 around 0.5: +-1.8%.
  EXPECT_TRUE(stored_ratio_precise(ratio_of({0.491, 0.5, 0.5, 0.5, 0.5, 0.509}), 0.95));
  EXPECT_FALSE(stored_ratio_precise(ratio_of({0.48, 0.5, 0.5, 0.5, 0.5, 0.51}), 0.95));
}

TEST(StoredRatio, TheRoundsNeededGrowWithTheSquareOfTheSpread) {
  RatioSummary ratio;
  ratio.log_ratio_mad_scaled = 0.0;
  EXPECT_EQ(stored_ratio_rounds_needed(ratio, 0.95), 6u);  // never fewer than an interval needs
  ratio.log_ratio_mad_scaled = 0.01;                       // (1.96 x 1.2533 x 1% / 2%)^2 = 1.5 -> 6
  EXPECT_EQ(stored_ratio_rounds_needed(ratio, 0.95), 6u);
  ratio.log_ratio_mad_scaled = 0.02;  // 6.03 -> 7
  EXPECT_EQ(stored_ratio_rounds_needed(ratio, 0.95), 7u);
  ratio.log_ratio_mad_scaled = 0.05;  // 37.7 -> 38
  EXPECT_EQ(stored_ratio_rounds_needed(ratio, 0.95), 38u);
  ratio.log_ratio_mad_scaled = 1e30;
  EXPECT_EQ(stored_ratio_rounds_needed(ratio, 0.95), 1000000u);
}

TEST(StoredRatio, RatioRoundsStopAtTwelveBaselineRounds) {
  SceneResult scene;
  for (int i = 0; i < 20; ++i) scene.runs.rounds.push_back(round_of(0.5, i < 6 ? 1.0 : 0.0));
  EXPECT_EQ(stored_ratio_rounds_left(scene), kStoredRatioMaxRounds - 6);
  for (int i = 0; i < 6; ++i) scene.runs.rounds.push_back(round_of(0.5, 1.0));
  EXPECT_EQ(stored_ratio_rounds_left(scene), 0u);
}

TEST(StoredRatio, TheStopRuleAsksForPrecisionOverTheRoundsTheBaselineJoined) {
  StoppingPolicy policy;
  policy.min_rounds = 1;
  policy.max_rounds = 100;
  const StopRule stop = stored_ratio_stop_rule(policy, 0.95);
  std::vector<Round> rounds;
  for (int i = 0; i < 5; ++i) rounds.push_back(round_of(0.5, 1.0));
  rounds.push_back(round_of(0.7, 0.0));  // no baseline: not part of the ratio
  EXPECT_EQ(stop(rounds, 1.0), StopDecision::continue_measuring);
  rounds.push_back(round_of(0.5, 1.0));
  EXPECT_EQ(stop(rounds, 1.0), StopDecision::stop_converged);
}

SceneResult measured_scene(const std::string& id, const std::vector<double>& base_seconds) {
  SceneResult scene;
  scene.entry.id = id;
  scene.ratios[Role::base] = ratio_of(base_seconds);
  return scene;
}

TEST(StoredRatio, TheClosingLineCountsThePreciseAndSaysWhyNotForTheRest) {
  ResultsDocument document;
  document.scenes.push_back(measured_scene("balls", {0.5, 0.5, 0.5, 0.5, 0.5, 0.5}));
  document.scenes.push_back(measured_scene("gears", {0.4, 0.5, 0.5, 0.5, 0.5, 0.6, 0.5, 0.5}));
  const std::string line =
      stored_ratio_line(document, GatePolicy{}, {{"gears", "no time left in the budget"}});
  EXPECT_NE(line.find("CI within +-2% on 1 of 2 scenes, from 6-8 baseline rounds"),
            std::string::npos)
      << line;
  EXPECT_NE(line.find("not: gears 0.500 [0.400, 0.600] (+-20.0%) from 8 baseline rounds (no "
                      "time left in the budget)"),
            std::string::npos)
      << line;
  EXPECT_EQ(stored_ratio_line(ResultsDocument{}, GatePolicy{}, {}), "");
}

// One round has no spread: its value is not printed as a zero-width interval, "+-0.0%".
TEST(StoredRatio, OneRoundIsSaidToHaveNoInterval) {
  ResultsDocument document;
  document.scenes.push_back(measured_scene("balls", {0.5}));
  const std::string line = stored_ratio_line(document, GatePolicy{}, {});
  EXPECT_NE(line.find("not: balls 0.500 from 1 baseline round, no interval (no ratio rounds)"),
            std::string::npos)
      << line;
  EXPECT_EQ(line.find("+-0.0%"), std::string::npos) << line;
}

// Counted costs (--timing sim) repeat: two rounds whose counts agree are a precise ratio, where
// timed rounds would need six; counts that spread beyond +-2% are still not.
TEST(StoredRatio, CountedRatiosArePreciseFromTwoAgreeingRounds) {
  ResultsDocument document;
  document.settings.timing_source = TimingSource::simulated;
  document.scenes.push_back(measured_scene("balls", {0.5, 0.50001}));
  document.scenes.push_back(measured_scene("gears", {0.4, 0.5}));
  const std::string line = stored_ratio_line(document, GatePolicy{}, {});
  EXPECT_NE(line.find("CI within +-2% on 1 of 2 scenes, from 2 baseline rounds (counted in "
                      "simulated cycles"),
            std::string::npos)
      << line;
  EXPECT_EQ(line.find("balls 0.5"), std::string::npos) << line;
  EXPECT_NE(line.find("not: gears"), std::string::npos) << line;
  document.settings.timing_source = TimingSource::process;
  EXPECT_NE(stored_ratio_line(document, GatePolicy{}, {}).find("on 0 of 2 scenes"),
            std::string::npos);
}

}  // namespace
}  // namespace raygate

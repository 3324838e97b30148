// The stopping policy bound to a scene's rounds (pipeline/stop_rules.h): the rules of run and of
// compare/bisect are one rule with different verdicts, and a verdict of one's own plugs in.
#include "pipeline/stop_rules.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "../runner/fake_executor.h"

namespace raygate {
namespace {

RunRecord timed(double seconds) {
  RunRecord run;
  run.ok = true;
  run.seconds = seconds;
  run.wall_seconds = seconds;
  return run;
}

// `count` rounds of (baseline, base, head) where head takes `factor` times base's time, with a
// small alternating wobble so intervals are not points.
std::vector<Round> compare_rounds(int count, double factor) {
  std::vector<Round> rounds;
  for (int i = 0; i < count; ++i) {
    const double wobble = 1.0 + 0.002 * (i % 3);
    Round round;
    round.order = {"baseline", "base", "head"};
    round.runs["baseline"] = timed(1.0 * wobble);
    round.runs["base"] = timed(2.0 * wobble);
    round.runs["head"] = timed(2.0 * factor * wobble * (1.0 + 0.001 * (i % 2)));
    rounds.push_back(round);
  }
  return rounds;
}

TEST(PipelineStopping, ChangeRuleStopsWhenTheVerdictIsDecided) {
  const StoppingPolicy policy;
  const ScenePolicy scene;  // 3% limit at 5% significance
  // One scene of a family at 1%: the decision sequence is bounded from the 9th round, the
  // equivalence sequence (5% each side) from the 7th.
  const StopRule rule = change_stop_rule(policy, scene, scene_levels(scene, 0.01));
  EXPECT_EQ(rule(compare_rounds(8, 1.2), 10.0), StopDecision::continue_measuring);
  EXPECT_EQ(rule(compare_rounds(9, 1.2), 10.0), StopDecision::stop_converged);
  EXPECT_EQ(rule(compare_rounds(6, 1.0), 10.0), StopDecision::continue_measuring);
  EXPECT_EQ(rule(compare_rounds(7, 1.0), 10.0), StopDecision::stop_converged);
  // A smaller share (six scenes) needs more rounds before a regression is called.
  const StopRule sixth = change_stop_rule(policy, scene, scene_levels(scene, 0.01 / 6));
  EXPECT_EQ(sixth(compare_rounds(11, 1.2), 10.0), StopDecision::continue_measuring);
  EXPECT_EQ(sixth(compare_rounds(12, 1.2), 10.0), StopDecision::stop_converged);
}

TEST(PipelineStopping, SceneLevelsSplitTheFamilyAndKeepTheScenesSignificance) {
  ScenePolicy scene;
  scene.significance = 0.1;
  const SequenceLevels levels = scene_levels(scene, 0.002);
  EXPECT_DOUBLE_EQ(levels.decision_alpha, 0.002);
  EXPECT_DOUBLE_EQ(levels.equivalence_alpha, 0.1);
  EXPECT_DOUBLE_EQ(levels.one_look_confidence, 0.9);
}

TEST(PipelineStopping, ChangeRuleSpendsTheBudgetOnAnInconclusiveScene) {
  StoppingPolicy policy;
  policy.max_rounds = 20;
  policy.max_seconds = 100.0;
  const ScenePolicy scene;
  const StopRule rule = change_stop_rule(policy, scene, scene_levels(scene, 0.01));
  // Alternating +1% / +5%: the interval straddles the 3% limit, so no verdict.
  std::vector<Round> rounds = compare_rounds(19, 1.0);
  for (std::size_t i = 0; i < rounds.size(); ++i) {
    rounds[i].runs["head"] = timed(2.0 * (i % 2 == 0 ? 1.01 : 1.05));
  }
  EXPECT_EQ(rule(rounds, 10.0), StopDecision::continue_measuring);
  EXPECT_EQ(rule(rounds, 100.0), StopDecision::stop_budget_time);
  rounds.push_back(rounds.front());
  EXPECT_EQ(rule(rounds, 10.0), StopDecision::stop_budget_rounds);
}

TEST(PipelineStopping, RatioRuleIsTheSameRuleWithTheRatioVerdict) {
  StoppingPolicy policy;
  policy.max_rounds = 4;
  std::vector<Round> rounds;
  for (int i = 0; i < 4; ++i) {
    Round round;
    round.runs["baseline"] = timed(1.0);
    round.runs["tracer"] = timed(i % 2 == 0 ? 1.0 : 3.0);  // far too noisy for a 1% target
    rounds.push_back(round);
    const std::vector<Round> so_far = rounds;
    EXPECT_EQ(ratio_stop_rule(policy, Role::tracer)(so_far, 1.0),
              stop_rule(policy, ratio_verdict(policy, Role::tracer))(so_far, 1.0));
  }
  EXPECT_EQ(ratio_stop_rule(policy, Role::tracer)(rounds, 1.0), StopDecision::stop_budget_rounds);
}

TEST(PipelineStopping, AVerdictOfOnesOwnDecidesOnItsOwnTerms) {
  // The seam another timing mode uses: decided after one round when it says so.
  const StopRule rule = stop_rule(StoppingPolicy{}, [](const std::vector<Round>& rounds) {
    return rounds.size() == 1 && rounds.front().runs.at("tracer").seconds == 7.0;
  });
  Round round;
  round.runs["tracer"] = timed(7.0);
  EXPECT_EQ(rule({round}, 0.0), StopDecision::stop_converged);
  round.runs["tracer"] = timed(8.0);
  EXPECT_EQ(rule({round}, 0.0), StopDecision::continue_measuring);
}

TEST(PipelineStopping, SuiteBudgetGivesEachSceneItsShareOfWhatIsLeft) {
  StoppingPolicy policy;
  policy.max_seconds = 100.0;
  policy.max_minutes = 6.0;  // 360 s for 4 scenes
  testing::FakeClock clock;
  SuiteBudget budget(policy, 4, clock);
  EXPECT_DOUBLE_EQ(budget.next_scene().max_seconds, 90.0);
  clock.advance(30.0);  // the first scene decided early: its unused 60 s go to the other three
  EXPECT_DOUBLE_EQ(budget.next_scene().max_seconds, 100.0);  // 110 s, but --max-seconds is 100
  clock.advance(300.0);
  EXPECT_DOUBLE_EQ(budget.next_scene().max_seconds, 15.0);  // 30 s left for two
  clock.advance(40.0);
  EXPECT_DOUBLE_EQ(budget.next_scene().max_seconds, 0.0);  // spent: one round, then stop
  EXPECT_EQ(budget.next_scene().max_rounds, policy.max_rounds);
}

TEST(PipelineStopping, SuiteBudgetKeepsAReserveForASecondVisit) {
  StoppingPolicy policy;
  policy.max_seconds = 1000.0;
  policy.max_minutes = 8.0;  // 480 s for 4 scenes and a reserve of 2 scenes' worth
  testing::FakeClock clock;
  SuiteBudget budget(policy, 4, clock, 2);
  EXPECT_DOUBLE_EQ(budget.next_scene().max_seconds, 80.0);
  clock.advance(80.0);
  EXPECT_DOUBLE_EQ(budget.next_scene().max_seconds, 80.0);
  clock.advance(80.0);
  EXPECT_DOUBLE_EQ(budget.next_scene().max_seconds, 80.0);
  clock.advance(20.0);                                       // this one decided early
  EXPECT_DOUBLE_EQ(budget.next_scene().max_seconds, 100.0);  // 300 s left for 1 + 2
  clock.advance(100.0);
  // Second pass: 200 s left for two undecided scenes without an estimate; the first has used
  // 80 s already, and the scheduler counts both visits' seconds.
  EXPECT_DOUBLE_EQ(budget.again(80.0, 2).max_seconds, 180.0);
  clock.advance(100.0);
  EXPECT_DOUBLE_EQ(budget.again(100.0, 1).max_seconds, 200.0);
  // --max-seconds bounds a scene's two visits together.
  clock.advance(50.0);
  policy.max_seconds = 120.0;
  SuiteBudget capped(policy, 1, clock);
  EXPECT_DOUBLE_EQ(capped.again(100.0, 1).max_seconds, 120.0);
}

TEST(PipelineStopping, ASecondVisitGetsWhatItIsEstimatedToNeedWithAMargin) {
  StoppingPolicy policy;
  policy.max_seconds = 1000.0;
  policy.max_minutes = 5.0;  // 300 s
  testing::FakeClock clock;
  SuiteBudget budget(policy, 4, clock, 1);
  clock.advance(200.0);  // 100 s left for 4 undecided scenes: an even share is 25 s
  // Estimated to need 30 s more: 1.5 times that, not the even 25 s that stops it short.
  EXPECT_DOUBLE_EQ(budget.again(40.0, 4, 30.0).max_seconds, 40.0 + 45.0);
  // A cheap one gets what it needs and no more: if that was too little, it is estimated again
  // and competes with the others for the rest.
  EXPECT_DOUBLE_EQ(budget.again(40.0, 4, 4.0).max_seconds, 40.0 + 6.0);
  // Never more than what is left of the whole budget.
  EXPECT_DOUBLE_EQ(budget.again(40.0, 4, 90.0).max_seconds, 40.0 + 100.0);
  // No estimate (a change on the limit): an even share.
  EXPECT_DOUBLE_EQ(budget.again(40.0, 4, std::numeric_limits<double>::infinity()).max_seconds,
                   40.0 + 25.0);
}

TEST(PipelineStopping, TheReserveIsAQuarterOfTheScenesAndNoneForOne) {
  EXPECT_EQ(revisit_reserve_scenes(0), 0u);
  EXPECT_EQ(revisit_reserve_scenes(1), 0u);
  EXPECT_EQ(revisit_reserve_scenes(2), 1u);
  EXPECT_EQ(revisit_reserve_scenes(13), 4u);
  EXPECT_EQ(revisit_reserve_scenes(16), 4u);
}

TEST(PipelineStopping, SuiteBudgetOfZeroMinutesLeavesThePolicyAlone) {
  StoppingPolicy policy;
  testing::FakeClock clock;
  SuiteBudget budget(policy, 2, clock);
  clock.advance(1e6);
  EXPECT_DOUBLE_EQ(budget.next_scene().max_seconds, policy.max_seconds);
  EXPECT_DOUBLE_EQ(budget.again(50.0, 1).max_seconds, policy.max_seconds);
}

}  // namespace
}  // namespace raygate

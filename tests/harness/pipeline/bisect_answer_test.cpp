// pipeline/bisect_answer: a bisection that did not find a first bad commit says why in words that
// are true: the bad end shown not worse, only not shown worse (INCONCLUSIVE: the sweep of
// 2026-11-28 found "-1.1% [-4.4%, +24.8%] ... is not worse"), or not measurable at all (it was
// reported as "not worse" too, and as "kind": "not_worse" in the JSON).
#include "pipeline/bisect_answer.h"

#include <gtest/gtest.h>

namespace raygate {
namespace {

BisectResult bad_end_judged(BisectOutcome outcome, BisectStepRecord step) {
  BisectResult result;
  result.outcome = outcome;
  result.first_bad = Revision{"HEAD", "", std::string(40, 'b'), "bbbbbbb", "bad", "A", ""};
  result.good.short_sha = "aaaaaaa";
  step.candidate = result.first_bad;
  result.steps.push_back(std::move(step));
  return result;
}

ChangeSummary change_of(double change, double lower, double upper) {
  ChangeSummary c;
  c.change = change;
  c.change_interval = {lower, upper};
  return c;
}

TEST(BisectAnswer, ABadEndShownNotWorseIsSaidSo) {
  const BisectResult result = bad_end_judged(
      BisectOutcome::bad_not_worse,
      {{}, BisectStep::good, "", change_of(-0.01, -0.02, 0.005), ChangeVerdict::unchanged, {}});
  EXPECT_EQ(bisect_text(result),
            "bbbbbbb is not worse than aaaaaaa on this scene; nothing to bisect\n");
  EXPECT_EQ(bisect_json(result, {})["result"]["kind"], "not_worse");
  EXPECT_EQ(bisect_exit_code(result), ExitCode::usage);
}

TEST(BisectAnswer, AnUndecidedBadEndIsNotCalledNotWorse) {
  const BisectResult result =
      bad_end_judged(BisectOutcome::bad_not_worse, {{},
                                                    BisectStep::good,
                                                    "",
                                                    change_of(-0.011, -0.044, 0.248),
                                                    ChangeVerdict::inconclusive,
                                                    {}});
  const std::string text = bisect_text(result);
  EXPECT_EQ(text.find("is not worse"), std::string::npos) << text;
  EXPECT_NE(text.find("could not tell whether bbbbbbb is worse than aaaaaaa"), std::string::npos)
      << text;
  EXPECT_NE(text.find("-1.1% [-4.4%, +24.8%], INCONCLUSIVE"), std::string::npos) << text;
  EXPECT_EQ(bisect_json(result, {})["result"]["kind"], "not_shown_worse");
}

TEST(BisectAnswer, ByImageABadEndWithTheSameImageIsSaidInWordsOfImagesNotSpeed) {
  BisectResult result = bad_end_judged(
      BisectOutcome::bad_not_worse,
      {{}, BisectStep::good, "", change_of(-0.0, -0.009, 0.001), ChangeVerdict::inconclusive, {}});
  result.metric = BisectMetric::image;
  EXPECT_EQ(bisect_text(result),
            "bbbbbbb's image is not shown to differ from aaaaaaa's on this scene; nothing to "
            "bisect by image\n");
  EXPECT_EQ(bisect_json(result, {})["result"]["kind"], "not_worse");
}

TEST(BisectAnswer, AnUnmeasurableBadEndSaysWhy) {
  const BisectResult result =
      bad_end_judged(BisectOutcome::bad_unmeasurable,
                     {{}, BisectStep::skipped, "the build failed (log: b.log)", {}, {}, {}});
  EXPECT_EQ(bisect_text(result),
            "bbbbbbb could not be measured (the build failed (log: b.log)); nothing to bisect\n");
  const nlohmann::json j = bisect_json(result, {});
  EXPECT_EQ(j["result"]["kind"], "bad_unmeasurable");
  EXPECT_EQ(j["result"]["reason"], "the build failed (log: b.log)");
  EXPECT_EQ(bisect_exit_code(result), ExitCode::infrastructure);
}

}  // namespace
}  // namespace raygate

// `raygate bisect` as a library call (pipeline/bisect.h): the search on its own with a judge of
// the test's, then the whole driver on a fixture history, each probe built for real and
// measured through the fake executor and clock.
#include "pipeline/bisect.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "pipeline_fixture.h"

namespace raygate::testing {
namespace {

// "c7": the name of the 8th commit of a made-up history.
std::string commit_name(int index) {
  std::string name(1, 'c');
  name += std::to_string(index);
  return name;
}

std::vector<Revision> history(int count) {
  std::vector<Revision> revisions(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    revisions[static_cast<std::size_t>(i)].sha = commit_name(i);
    revisions[static_cast<std::size_t>(i)].short_sha = commit_name(i);
  }
  return revisions;
}

// A judge that says bad from `first_bad` on, skips `skipped`, and counts its calls.
struct ScriptedJudge {
  int first_bad;
  std::vector<int> skipped;
  std::map<std::string, int> asked;

  BisectStep operator()(const Revision& candidate) {
    ++asked[candidate.sha];
    const int index = std::stoi(candidate.sha.substr(1));
    if (std::find(skipped.begin(), skipped.end(), index) != skipped.end()) {
      return BisectStep::skipped;
    }
    return index >= first_bad ? BisectStep::bad : BisectStep::good;
  }
};

TEST(BisectSearch, FindsTheFirstBadInLogarithmicSteps) {
  const std::vector<Revision> candidates = history(16);
  for (int culprit = 0; culprit < 16; ++culprit) {
    ScriptedJudge judge{culprit, {}, {}};
    const BisectResult result =
        bisect_search(candidates, [&](const Revision& r) { return judge(r); });
    EXPECT_EQ(result.outcome, BisectOutcome::found) << culprit;
    EXPECT_EQ(result.first_bad.sha, commit_name(culprit));
    EXPECT_LE(judge.asked.size(), 6u) << culprit;  // the last, then at most log2(16) + 1
    for (const auto& [sha, times] : judge.asked) EXPECT_EQ(times, 1) << sha;
  }
}

TEST(BisectSearch, ABadEndThatIsNotWorseOrNotMeasurableEndsTheSearch) {
  const std::vector<Revision> candidates = history(5);
  ScriptedJudge never{99, {}, {}};
  EXPECT_EQ(bisect_search(candidates, [&](const Revision& r) { return never(r); }).outcome,
            BisectOutcome::bad_not_worse);
  ScriptedJudge broken{0, {4}, {}};
  EXPECT_EQ(bisect_search(candidates, [&](const Revision& r) { return broken(r); }).outcome,
            BisectOutcome::bad_unmeasurable);
  EXPECT_EQ(broken.asked.size(), 1u);
}

// Sweep 13: the bad end read +10.0% [-16.4%, +145.5%] INCONCLUSIVE was taken as bad, and bisect
// named a culprit of a tracer identical at every commit. The bad end must be shown worse; a step
// between the ends may still be decided by its estimate.
TEST(BisectSearch, AnUndecidedBadEndIsNotBadButAnUndecidedStepBetweenIsByItsEstimate) {
  ChangeSummary undecided;
  undecided.rounds = 4;
  undecided.change = 0.10;
  undecided.change_interval = {-0.164, 1.455};
  EXPECT_FALSE(slower_step(undecided, 0.03, true));
  EXPECT_TRUE(slower_step(undecided, 0.03, false));
  ChangeSummary shown = undecided;
  shown.rounds = 20;  // enough for the order-statistic interval to be bounded
  shown.change_interval = {0.06, 0.14};
  EXPECT_TRUE(slower_step(shown, 0.03, true));
}

TEST(BisectSearch, SkipsAroundTheCulpritLeaveARange) {
  const std::vector<Revision> candidates = history(8);
  ScriptedJudge judge{5, {3, 4}, {}};  // c3, c4 do not build; c5 is the culprit
  const BisectResult result =
      bisect_search(candidates, [&](const Revision& r) { return judge(r); });
  EXPECT_EQ(result.outcome, BisectOutcome::hidden_by_skips);
  EXPECT_EQ(result.first_bad.sha, "c5");
  EXPECT_EQ(result.unmeasured, 2u);
  // A skip away from the culprit does not hide it.
  ScriptedJudge clear{5, {1}, {}};
  EXPECT_EQ(bisect_search(candidates, [&](const Revision& r) { return clear(r); }).first_bad.sha,
            "c5");
}

TEST(BisectSearch, AnEmptyRangeIsAUsageErrorNotACrash) {
  ScriptedJudge judge{0, {}, {}};
  EXPECT_THROW(bisect_search({}, [&](const Revision& r) { return judge(r); }), UsageError);
  EXPECT_TRUE(judge.asked.empty());
}

class BisectPipelineTest : public PipelineTest {
 protected:
  BisectResult bisect_range(const std::string& good, const std::string& bad) {
    context_.scenes.resize(1);  // bisect follows one scene
    const Repository repository = Repository::open(repo_.path().string(), context_.cache_dir);
    return bisect({context_, baseline_, repository, good, bad, BisectMetric::ratio}, io_);
  }
};

TEST_F(BisectPipelineTest, FindsTheCommitThatMadeTheSceneSlower) {
  const std::string good = commit_tracer("2.0", "good");
  commit_tracer("2.0", "docs");
  commit_tracer("2.01", "a harmless 0.5%");
  const std::string culprit = commit_tracer("2.4", "the culprit: 20% slower");
  commit_tracer("2.4", "later");
  const std::string bad = commit_tracer("2.4", "bad");
  const BisectResult result = bisect_range(good, bad);
  EXPECT_EQ(result.outcome, BisectOutcome::found);
  EXPECT_EQ(result.first_bad.sha, culprit);
  EXPECT_EQ(result.good.sha, good);
  EXPECT_EQ(progress_.lines_with("bisecting 5 commits").size(), 1u);
  EXPECT_FALSE(progress_.lines_with("-> bad").empty());
  EXPECT_FALSE(progress_.lines_with("-> good").empty());
  // Each commit is built (or taken from the build cache) once: the good one at the first step,
  // each judged one at its own.
  const auto builds_of = [this](const std::string& sha) {
    return std::count_if(progress_.statuses.begin(), progress_.statuses.end(),
                         [&](const std::string& s) { return s.find("(" + sha + ")") != s.npos; });
  };
  EXPECT_EQ(builds_of(good), 1);
  ASSERT_FALSE(result.steps.empty());
  for (const BisectStepRecord& step : result.steps) EXPECT_EQ(builds_of(step.candidate.sha), 1);
}

TEST_F(BisectPipelineTest, ACommitThatDoesNotBuildIsSkipped) {
  const std::string good = commit_tracer("2.0", "good");
  commit_tracer("2.0", "docs");
  commit_tracer("", "broken build");  // probed first: the middle of the range
  commit_tracer("2.0", "fixed");
  const std::string culprit = commit_tracer("2.4", "the culprit");
  const std::string bad = commit_tracer("2.4", "bad");
  const BisectResult result = bisect_range(good, bad);
  EXPECT_EQ(result.outcome, BisectOutcome::found);
  EXPECT_EQ(result.first_bad.sha, culprit);
  EXPECT_EQ(progress_.lines_with("does not build").size(), 1u);
}

TEST_F(BisectPipelineTest, ACommitThatDoesNotBuildRightBeforeTheCulpritHidesIt) {
  const std::string good = commit_tracer("2.0", "good");
  commit_tracer("", "broken build");
  const std::string culprit = commit_tracer("2.4", "the culprit");
  const std::string bad = commit_tracer("2.4", "bad");
  const BisectResult result = bisect_range(good, bad);
  EXPECT_EQ(result.outcome, BisectOutcome::hidden_by_skips);
  EXPECT_EQ(result.first_bad.sha, culprit);
  EXPECT_EQ(result.unmeasured, 1u);
}

TEST_F(BisectPipelineTest, ABadEndThatIsNotSlowerHasNothingToBisect) {
  const std::string good = commit_tracer("2.0", "good");
  const std::string bad = commit_tracer("2.0", "not slower");
  EXPECT_EQ(bisect_range(good, bad).outcome, BisectOutcome::bad_not_worse);
}

// The UsageError bisect_range(good, bad) throws, or "" when it throws none. Nothing may have
// been built or measured by then.
class BisectRangeTest : public BisectPipelineTest {
 protected:
  std::string refusal(const std::string& good, const std::string& bad) {
    try {
      bisect_range(good, bad);
      return "";
    } catch (const UsageError& e) {
      EXPECT_TRUE(progress_.statuses.empty()) << "built before refusing";
      EXPECT_TRUE(progress_.lines.empty()) << "bisected before refusing";
      return e.what();
    }
  }
};

TEST_F(BisectRangeTest, TheSameCommitTwiceIsAnEmptyRange) {
  commit_tracer("2.0", "good");
  const std::string only = commit_tracer("2.4", "the only one");
  const std::string why = refusal(only, only);
  EXPECT_NE(why.find("are the same commit " + only.substr(0, 7)), std::string::npos) << why;
  EXPECT_NE(why.find("give --good a revision older than --bad"), std::string::npos) << why;
  EXPECT_NE(refusal("main", only).find("same commit"), std::string::npos);
}

TEST_F(BisectRangeTest, ATagAndItsShaAreTheSameCommit) {
  const std::string tagged = commit_tracer("2.0", "release");
  repo_.annotated_tag("v1.0", "release 1.0");
  repo_.tag("light");
  EXPECT_NE(refusal("v1.0", tagged).find("same commit"), std::string::npos);
  EXPECT_NE(refusal(tagged, "v1.0").find("same commit"), std::string::npos);
  EXPECT_NE(refusal("light", "v1.0").find("same commit"), std::string::npos);
}

TEST_F(BisectRangeTest, AGoodEndNewerThanTheBadEndIsRefusedAsSwapped) {
  const std::string older = commit_tracer("2.0", "older");
  commit_tracer("2.0", "middle");
  const std::string newer = commit_tracer("2.4", "newer");
  const std::string why = refusal(newer, older);
  EXPECT_NE(why.find("is not an ancestor of"), std::string::npos) << why;
  EXPECT_NE(why.find("a descendant of " + older.substr(0, 7)), std::string::npos) << why;
  EXPECT_NE(why.find("swapped"), std::string::npos) << why;
}

TEST_F(BisectRangeTest, UnrelatedHistoriesAreRefused) {
  const std::string first = commit_tracer("2.0", "first history");
  repo_.write("README", "another project\n");
  CommitOptions root;
  root.root = true;
  repo_.commit("a second root", root);
  const std::string other = commit_tracer("2.4", "on the second root");
  const std::string why = refusal(first, other);
  EXPECT_NE(why.find("unrelated histories"), std::string::npos) << why;
}

TEST_F(BisectRangeTest, DivergedEndsAreRefusedWithTheirCommonAncestor) {
  const std::string base = commit_tracer("2.0", "common");
  repo_.branch("side");
  const std::string on_main = commit_tracer("2.4", "on main");
  repo_.switch_to("side");
  const std::string on_side = commit_tracer("2.0", "on side");
  const std::string why = refusal(on_side, on_main);
  EXPECT_NE(why.find("diverged after " + base.substr(0, 7) + " common"), std::string::npos) << why;
}

TEST_F(BisectPipelineTest, AMergeOnlyRangeNamesTheMergeAndTheRangeItBroughtIn) {
  // main: good - M, where M merges a side branch holding the slowdown. Following first parents
  // the range is M alone: the answer is M, and the note says which range to bisect next.
  const std::string good = commit_tracer("2.0", "good");
  repo_.branch("side");
  repo_.switch_to("side");
  commit_tracer("2.0", "side: docs");
  const std::string side_tip = commit_tracer("2.4", "side: the culprit");
  repo_.switch_to("main");
  repo_.write("cost", "2.4\n");  // the merged tree: the side's cost
  CommitOptions merge;
  merge.merge_parents = {side_tip};
  const std::string merge_sha = repo_.commit("merge side", merge);

  const BisectResult result = bisect_range(good, merge_sha);
  EXPECT_EQ(result.outcome, BisectOutcome::found);
  EXPECT_EQ(result.first_bad.sha, merge_sha);
  EXPECT_EQ(result.candidates, 1u);
  EXPECT_NE(result.merge_note.find("is a merge"), std::string::npos) << result.merge_note;
  EXPECT_NE(
      result.merge_note.find("--good " + good.substr(0, 7) + " --bad " + side_tip.substr(0, 7)),
      std::string::npos)
      << result.merge_note;
}

TEST_F(BisectPipelineTest, AnOrdinaryFirstBadCommitHasNoMergeNote) {
  const std::string good = commit_tracer("2.0", "good");
  const std::string bad = commit_tracer("2.4", "bad");
  const BisectResult result = bisect_range(good, bad);
  EXPECT_EQ(result.outcome, BisectOutcome::found);
  EXPECT_EQ(result.merge_note, "");
}

}  // namespace
}  // namespace raygate::testing

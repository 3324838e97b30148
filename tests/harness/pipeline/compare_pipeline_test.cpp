// `raygate compare` as a library call (pipeline/compare_measurement.h): base and head of the
// fixture repository built for real, their runs answered by the fake executor and clock.
#include "pipeline/compare_measurement.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "gate/verdict.h"
#include "measure/confidence_sequence.h"
#include "pipeline_fixture.h"

namespace raygate::testing {
namespace {

class ComparePipelineTest : public PipelineTest {
 protected:
  MeasuredDocument compare(const std::string& base, const std::string& head) {
    const Repository repository = Repository::open(repo_.path().string(), context_.cache_dir);
    return measure_compare({context_, baseline_, repository.location(),
                            repository.checkout(base), repository.checkout(head), {}},
                           io_);
  }
};

TEST_F(ComparePipelineTest, ASlowerHeadIsRegressedOnEveryScene) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.4", "head: 20% slower");
  const auto [document, path, unwritten] = compare(base, head);
  EXPECT_TRUE(unwritten.empty());
  EXPECT_EQ(document.kind, DocumentKind::compare);
  EXPECT_TRUE(document.complete);
  ASSERT_EQ(document.revisions.size(), 2u);
  EXPECT_EQ(document.revisions[0].role, Role::base);
  EXPECT_EQ(document.revisions[0].worktree.sha, base);
  EXPECT_EQ(document.revisions[1].role, Role::head);
  ASSERT_EQ(document.scenes.size(), 2u);
  for (const SceneResult& scene : document.scenes) {
    ASSERT_TRUE(scene.change.has_value()) << scene.entry.id;
    EXPECT_NEAR(scene.change->change, 0.2, 1e-9);
    EXPECT_EQ(scene.change_verdict, ChangeVerdict::regressed);
    // Two scenes share the family's 1%: each decision sequence (0.5% each side) is bounded from
    // its 11th round, and with exact times the verdict is decided then.
    EXPECT_EQ(min_values_for_median_sequence(0.01 / 2), 11u);
    EXPECT_EQ(scene.runs.rounds.size(), 11u);
    EXPECT_EQ(scene.runs.stop_reason, "stop_converged");
    EXPECT_DOUBLE_EQ(scene.ratio(Role::base)->ratio, 2.0);
    EXPECT_DOUBLE_EQ(scene.ratio(Role::head)->ratio, 2.4);
  }
  EXPECT_TRUE(std::filesystem::exists(path));
}

TEST_F(ComparePipelineTest, AnEqualHeadIsUnchangedAndItsImageMatchesBase) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.0", "head: a comment");
  const auto [document, path, unwritten] = compare(base, head);
  for (const SceneResult& scene : document.scenes) {
    EXPECT_EQ(scene.change_verdict, ChangeVerdict::unchanged) << scene.entry.id;
    bool checked_against_base = false;
    for (const ImageCheck& check : scene.images) {
      if (check.reference != ImageReference::base) continue;
      checked_against_base = true;
      EXPECT_EQ(check.verdict, ImageVerdict::pass);
    }
    EXPECT_TRUE(checked_against_base);
  }
}

TEST_F(ComparePipelineTest, AnUndecidedChangeGetsRoundsUntilTheBudget) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.06", "head: 3% slower, right at the limit");
  set_tracer_noise({1.0, 1.0, 1.04, 0.97});  // base and head alternate through these
  context_.stopping.max_rounds = 10;
  const auto [document, path, unwritten] = compare(base, head);
  for (const SceneResult& scene : document.scenes) {
    EXPECT_EQ(scene.change_verdict, ChangeVerdict::inconclusive) << scene.entry.id;
    EXPECT_EQ(scene.runs.rounds.size(), 10u);
    EXPECT_EQ(scene.runs.stop_reason, "stop_budget_rounds");
  }
  // One closing line names every undecided scene, its change and how wide its interval is.
  const std::vector<std::string> undecided = progress_.lines_with("undecided (INCONCLUSIVE): ");
  ASSERT_EQ(undecided.size(), 1u);
  for (const SceneResult& scene : document.scenes) {
    EXPECT_NE(undecided[0].find(scene.entry.id + " +"), std::string::npos) << undecided[0];
  }
  // Its 10 rounds are one short of a bounded decision sequence for two scenes.
  EXPECT_NE(undecided[0].find("after 10 rounds, no 99% CS yet (it needs 11 rounds at least, "),
            std::string::npos)
      << undecided[0];
  // And the runner's noise, with what it would have to be below for the rounds the scenes got:
  // at 10 rounds the 90% equivalence sequence is the rounds' range, about +-1.55 sigma.
  const std::vector<std::string> notes = evaluate_gate(document, context_.policy).notes;
  const auto noise = std::find_if(notes.begin(), notes.end(), [](const std::string& note) {
    return note.starts_with("runner noise: ");
  });
  ASSERT_NE(noise, notes.end());
  EXPECT_NE(noise->find("median of 2 scenes); in the 10 rounds a scene typically got, an "
                        "unchanged scene is decided within the 3.0% limit below about 1.9%. "),
            std::string::npos)
      << *noise;
}

TEST_F(ComparePipelineTest, ScenesTheirShareLeftUndecidedGetASecondVisit) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.0", "head: the same speed");
  // A round costs 5 s while the baseline joins (its first 3), then 4 s; warm-ups 5 s. An A/A
  // scene is UNCHANGED from its 7th round (36 s). 90 s for two scenes and a reserve of one:
  // the first pass gives each about 30 s, too little, and the second pass the rest.
  context_.stopping.max_minutes = 1.5;
  const double started = clock_.now_seconds();
  const auto [document, path, unwritten] = compare(base, head);
  ASSERT_EQ(document.scenes.size(), 2u);
  EXPECT_EQ(progress_.lines_with("[again ").size(), 2u);
  for (const SceneResult& scene : document.scenes) {
    EXPECT_EQ(scene.change_verdict, ChangeVerdict::unchanged) << scene.entry.id;
    EXPECT_EQ(scene.runs.stop_reason, "stop_converged") << scene.entry.id;
    EXPECT_EQ(scene.runs.warmup.at("head").size(), 1u) << "warmed up once, on the first visit";
    EXPECT_EQ(progress_.lines_with("[again ").size(), 2u);
    EXPECT_EQ(progress_.lines_with("] " + scene.entry.id).size(), 2u) << scene.entry.id;
  }
  EXPECT_LE(clock_.now_seconds() - started, 90.0 + 5.0)
      << "the budget, and at most the round in flight";
  EXPECT_TRUE(progress_.lines_with("undecided (INCONCLUSIVE)").empty());
  for (const std::string& note : evaluate_gate(document, context_.policy).notes) {
    EXPECT_EQ(note.find("runner noise"), std::string::npos) << "said only when it mattered";
  }
}

TEST_F(ComparePipelineTest, TheSecondPassVisitsAgainAndBacksOffAScenesThatOutlivedItsEstimate) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.0", "head: the same speed");
  // Noisy rounds (head/base about +2% with a few percent of spread) and 120 s for two scenes:
  // neither is decided in the first pass. tetra, the cheaper by its estimate, gets what it is
  // estimated to need, and is still undecided: its estimate doubles, so balls goes next; balls
  // outlives its estimate too, and its next visit is twice as long. The visits go on until the
  // time is gone.
  set_tracer_noise({1.0, 1.02, 0.99, 1.01, 0.98, 1.0, 1.03, 0.99});
  context_.stopping.max_minutes = 2.0;
  const double started = clock_.now_seconds();
  const auto [document, path, unwritten] = compare(base, head);
  ASSERT_EQ(document.scenes.size(), 2u);
  const auto rounds_in = [&](const std::string& prefix) -> std::size_t {
    const std::vector<std::string> lines = progress_.lines_with(prefix);
    if (lines.size() != 1) return 0;
    const std::size_t end = lines[0].find(" rounds, ");
    const std::size_t begin = lines[0].rfind("  ", end) + 2;
    return std::stoul(lines[0].substr(begin, end - begin));
  };
  const std::size_t tetra_first = rounds_in("[1/2] tetra");
  const std::size_t tetra_again = rounds_in("[again 1, 2 undecided] tetra");
  const std::size_t balls_first = rounds_in("[2/2] balls");
  const std::size_t balls_again = rounds_in("[again 2, 2 undecided] balls");
  const std::size_t balls_third = rounds_in("[again 3, 2 undecided] balls");
  ASSERT_GT(tetra_again, tetra_first);
  ASSERT_GT(balls_again, balls_first);
  ASSERT_GT(balls_third, balls_again);
  EXPECT_GT(balls_third - balls_again, balls_again - balls_first) << "backed off: a longer visit";
  EXPECT_LE(clock_.now_seconds() - started, 120.0 + 5.0)
      << "the budget, and at most the round in flight";
}

TEST_F(ComparePipelineTest, OpensWithWhatItCompares) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.0", "head");
  compare(base, head);
  ASSERT_FALSE(progress_.lines.empty());
  EXPECT_EQ(progress_.lines.front().rfind("comparing fake-cost-tracer " + base.substr(0, 7), 0),
            0u)
      << progress_.lines.front();
  EXPECT_EQ(progress_.lines_with("(base) with").size(), 1u);
}

}  // namespace
}  // namespace raygate::testing

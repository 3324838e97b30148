// `raygate compare` as a library call (pipeline/compare_measurement.h): base and head of the
// fixture repository built for real, their runs answered by the fake executor and clock.
#include "pipeline/compare_measurement.h"

#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <map>

#include "core/interrupt.h"
#include "gate/verdict.h"
#include "measure/confidence_sequence.h"
#include "measure/simulated_cost.h"
#include "measure/stopping_policy.h"
#include "pipeline/compare_family.h"
#include "pipeline/stop_rules.h"
#include "pipeline/stored_ratio.h"
#include "pipeline_fixture.h"
#include "results/results.h"

namespace raygate::testing {
namespace {

std::vector<double> one_run_in_four_slowed();

// Factors for set_tracer_noise(): within +-`amplitude`, no two runs alike.
std::vector<double> wandering(double amplitude) {
  std::vector<double> factors;
  for (int k = 0; k < 97; ++k) factors.push_back(1.0 + amplitude * std::sin(1.7 * k));
  return factors;
}

class ComparePipelineTest : public PipelineTest {
 protected:
  // An A/A compare of two scenes in 6 minutes under one_run_in_four_slowed(), the second pass
  // free to choose the fastest of two or not.
  MeasuredDocument compare_beside_one_sided_noise(bool repeat_where_it_pays) {
    const std::string base = commit_tracer("2.0", "base");
    const std::string head = commit_tracer("2.0", "head: the same speed");
    set_tracer_noise(one_run_in_four_slowed());
    context_.repeat_where_it_pays = repeat_where_it_pays;
    context_.stopping.max_minutes = 6.0;
    MeasuredDocument measured = compare(base, head);
    EXPECT_EQ(measured.document.scenes.size(), 2u);
    return measured;
  }

  // A head 20% slower than base, the tracer's runs wandering within +-`amplitude`, the baseline
  // in the first kChangeBaselineRounds rounds as compare's default has it.
  MeasuredDocument compare_slower_head_with_noise(double amplitude) {
    const std::string base = commit_tracer("2.0", "base");
    const std::string head = commit_tracer("2.4", "head: 20% slower");
    set_tracer_noise(wandering(amplitude));
    context_.schedule.normalizer_rounds = kChangeBaselineRounds;
    return compare(base, head);
  }

  MeasuredDocument compare(const std::string& base, const std::string& head) {
    const Repository repository = Repository::open(repo_.path().string(), context_.cache_dir);
    return measure_compare({context_,
                            baseline_,
                            repository.location(),
                            repository.checkout(base),
                            repository.checkout(head),
                            {}},
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

// The baseline joins a scene's first 3 rounds; where base's ratio over them is not yet a 95%
// interval within +-2% and its spread says 12 would make it one, the scene gets ratio rounds
// after the decisions, the baseline in each, up to 12 of them; the change stays judged on the
// rounds it was decided on.
TEST_F(ComparePipelineTest, AnImpreciseStoredRatioGetsRatioRoundsThatLeaveTheVerdict) {
  const auto [document, path, unwritten] = compare_slower_head_with_noise(0.025);
  ASSERT_EQ(document.scenes.size(), 2u);
  for (const SceneResult& scene : document.scenes) {
    EXPECT_EQ(scene.change_verdict, ChangeVerdict::regressed) << scene.entry.id;
    const std::vector<Round>& rounds = scene.runs.rounds;
    // The rounds before the ratio rounds: up to the last one the baseline did not join.
    std::size_t decided_on = 0;
    for (std::size_t i = 0; i < rounds.size(); ++i) {
      if (!rounds[i].runs.contains("baseline")) decided_on = i + 1;
    }
    ASSERT_GT(decided_on, kChangeBaselineRounds) << scene.entry.id;
    ASSERT_GT(rounds.size(), decided_on) << scene.entry.id << ": no ratio rounds";
    EXPECT_EQ(scene.runs.stop_reason, "stop_converged") << "the change's, not the ratio rounds'";
    const std::vector<CompareRound> samples = compare_samples(rounds);
    const ScenePolicy& policy = context_.policy.for_scene(scene.entry.id);
    const auto judged_on = [&](std::size_t n) {
      return measured_change(std::span<const CompareRound>(samples.data(), n),
                             change_bootstrap(policy), false,
                             scene_levels(policy, scene_decision_alpha(context_.policy, 2)));
    };
    const ChangeSummary decided = judged_on(decided_on);
    EXPECT_DOUBLE_EQ(scene.change->change_interval.lower, decided.change_interval.lower);
    EXPECT_DOUBLE_EQ(scene.change->change_interval.upper, decided.change_interval.upper);
    const ChangeSummary on_all = judged_on(rounds.size());
    EXPECT_TRUE(on_all.log_change_median != decided.log_change_median ||
                on_all.change_interval.lower != decided.change_interval.lower ||
                on_all.change_interval.upper != decided.change_interval.upper)
        << "the test needs ratio rounds that would move the change";
    const RatioSummary* stored = scene.ratio(Role::base);
    ASSERT_NE(stored, nullptr);
    EXPECT_EQ(stored->rounds, round_samples(rounds, Role::base).size());
    EXPECT_GT(stored->rounds, kChangeBaselineRounds);
    EXPECT_LE(stored->rounds, kStoredRatioMaxRounds);
  }
  EXPECT_EQ(progress_.lines_with("[ratio 1/").size(), 1u);
  EXPECT_EQ(progress_.lines_with("stored ratios (base against the baseline").size(), 1u);
}

// Rounds that differ by several percent would need dozens of baseline rounds for a ratio within
// +-2%: none are spent, and the closing line says what it would take.
TEST_F(ComparePipelineTest, ATooNoisyStoredRatioGetsNoRatioRoundsAndTheLineSaysWhy) {
  const auto [document, path, unwritten] = compare_slower_head_with_noise(0.08);
  for (const SceneResult& scene : document.scenes) {
    EXPECT_EQ(round_samples(scene.runs.rounds, Role::base).size(), kChangeBaselineRounds);
  }
  EXPECT_TRUE(progress_.lines_with("[ratio ").empty());
  const std::vector<std::string> line = progress_.lines_with("stored ratios");
  ASSERT_EQ(line.size(), 1u);
  EXPECT_NE(line[0].find("CI within +-2% on 0 of 2 scenes, from 3 baseline rounds"),
            std::string::npos)
      << line[0];
  EXPECT_NE(line[0].find("baseline rounds would make it +-2%, and ratio rounds stop at 12)"),
            std::string::npos)
      << line[0];
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
                        "unchanged scene is shown within the 3.0% limit (UNCHANGED) only when "
                        "its rounds differ by less than about 1.9%. "),
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
  EXPECT_EQ(progress_.lines_with("[second pass ").size(), 2u);
  for (const SceneResult& scene : document.scenes) {
    EXPECT_EQ(scene.change_verdict, ChangeVerdict::unchanged) << scene.entry.id;
    EXPECT_EQ(scene.runs.stop_reason, "stop_converged") << scene.entry.id;
    EXPECT_EQ(scene.runs.warmup.at("head").size(), 1u) << "warmed up once, on the first visit";
    EXPECT_EQ(progress_.lines_with("[second pass ").size(), 2u);
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
  // Noisy rounds (head/base about +4% with a few percent of spread) and 2 min for two scenes:
  // neither is decided in the first pass. The cheaper by its estimate gets what it is estimated
  // to need, and is still undecided: its estimate doubles, so the other goes next. A scene's
  // visit after one it outlived is longer (unless the budget's end cuts it). The visits go on
  // until the time is gone.
  set_tracer_noise({1.0, 1.04, 0.98, 1.02, 0.96, 1.0, 1.06, 0.98});
  context_.stopping.max_minutes = 2.0;
  const double started = clock_.now_seconds();
  const auto [document, path, unwritten] = compare(base, head);
  ASSERT_EQ(document.scenes.size(), 2u);
  // Each line's scene and its rounds so far.
  struct Visit {
    std::string scene;
    std::size_t rounds = 0;
  };
  const auto visit_in = [&](const std::string& prefix) -> Visit {
    const std::vector<std::string> lines = progress_.lines_with(prefix);
    if (lines.size() != 1) return {};
    const std::size_t name = lines[0].find("] ") + 2;
    const std::size_t end = lines[0].find(" rounds, ");
    const std::size_t begin = lines[0].rfind("  ", end) + 2;
    return {lines[0].substr(name, lines[0].find(' ', name) - name),
            std::stoul(lines[0].substr(begin, end - begin))};
  };
  const Visit first = visit_in("[second pass 1, 2 scenes undecided]");
  const Visit second = visit_in("[second pass 2, 2 scenes undecided]");
  ASSERT_FALSE(first.scene.empty());
  ASSERT_FALSE(second.scene.empty());
  EXPECT_NE(second.scene, first.scene) << "backed off: the other scene goes next";
  // Rounds each visit added, by scene: a scene's visit after one it outlived is longer.
  std::map<std::string, std::size_t> rounds_so_far{{"tetra", visit_in("[1/2] tetra").rounds},
                                                   {"balls", visit_in("[2/2] balls").rounds}};
  std::vector<Visit> visits;
  for (std::size_t k = 1; k < 20; ++k) {
    const Visit visit = visit_in(fmt::format("[second pass {}, 2 scenes undecided]", k));
    if (visit.scene.empty()) break;
    visits.push_back(visit);
  }
  // The last visit is cut short by the end of the budget, so only the ones before it count.
  std::map<std::string, std::vector<std::size_t>> added;
  for (std::size_t k = 0; k + 1 < visits.size(); ++k) {
    added[visits[k].scene].push_back(visits[k].rounds - rounds_so_far[visits[k].scene]);
    rounds_so_far[visits[k].scene] = visits[k].rounds;
  }
  for (const auto& [scene, lengths] : added) {
    for (std::size_t k = 1; k < lengths.size(); ++k) {
      EXPECT_GT(lengths[k], lengths[k - 1]) << scene << " visit " << k + 1 << ": backed off";
    }
  }
  EXPECT_LE(clock_.now_seconds() - started, 120.0 + 5.0)
      << "the budget, and at most the round in flight";
}

// One tracer run in four slowed by 2-14% (the host took the CPU), the others within 0.3%: one
// run per round, every second round reads several percent slower or faster, and the rounds
// decide late if at all; of each side's two runs in a pair of rounds at most one is slowed, so
// the fastest of two reads within 0.3%. The second pass, seeing that in pairs of a scene's
// rounds, visits with the fastest of two, and the scene is decided.
std::vector<double> one_run_in_four_slowed() {
  std::vector<double> factors;
  for (int i = 0; i < 28; ++i) {
    factors.push_back(i % 4 == 0 ? 1.02 + 0.02 * (i / 4) : 1.0 + 0.001 * ((i * 3) % 7 - 3));
  }
  return factors;
}

TEST_F(ComparePipelineTest, TheSecondPassGivesOneSidedNoiseTheFastestOfTwo) {
  const MeasuredDocument measured = compare_beside_one_sided_noise(true);
  const std::vector<std::string> visits = progress_.lines_with("[second pass ");
  ASSERT_FALSE(visits.empty());
  EXPECT_NE(visits.front().find("of them the fastest of 2 runs"), std::string::npos)
      << visits.front();
  for (const SceneResult& scene : measured.document.scenes) {
    EXPECT_EQ(scene.change_verdict, ChangeVerdict::unchanged) << scene.entry.id;
    EXPECT_NE(repeats_note(scene.runs.rounds), "") << scene.entry.id;
  }
}

// The first pass chooses too: after ten one-run rounds, a scene whose pairs of rounds show the
// fastest of two decides it sooner takes it for its rounds to come.
TEST_F(ComparePipelineTest, TheFirstPassTakesTheFastestOfTwoOnceTenRoundsShowItPays) {
  const MeasuredDocument measured = compare_beside_one_sided_noise(true);
  const std::vector<std::string> first_pass = progress_.lines_with("/2] ");
  ASSERT_EQ(first_pass.size(), 2u);
  for (const std::string& line : first_pass) {
    EXPECT_NE(line.find("of them the fastest of 2 runs"), std::string::npos) << line;
  }
  for (const SceneResult& scene : measured.document.scenes) {
    const std::vector<Round>& rounds = scene.runs.rounds;
    ASSERT_GT(rounds.size(), 10u) << scene.entry.id;
    for (std::size_t i = 0; i < 10; ++i) EXPECT_EQ(runs_per_contender(rounds[i]), 1u) << i;
    EXPECT_EQ(runs_per_contender(rounds[10]), 2u) << scene.entry.id;
  }
}

// The same without the choice (--repeats given): the second pass goes on with one run, and
// the same noise leaves the scenes undecided.
TEST_F(ComparePipelineTest, WithoutTheChoiceTheSameNoiseStaysUndecided) {
  const MeasuredDocument measured = compare_beside_one_sided_noise(false);
  for (const SceneResult& scene : measured.document.scenes) {
    EXPECT_EQ(scene.change_verdict, ChangeVerdict::inconclusive) << scene.entry.id;
    EXPECT_EQ(repeats_note(scene.runs.rounds), "") << scene.entry.id;
  }
}

// Ctrl-C during the second pass: the visit in flight ends, and the document keeps every round
// measured so far, the visits' included, marked incomplete.
TEST_F(ComparePipelineTest, AnInterruptInTheSecondPassKeepsTheRoundsOfItsVisits) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.0", "head: the same speed");
  context_.stopping.max_minutes = 1.5;  // as above: both scenes need a second visit
  std::size_t rounds_at_signal = 0;
  std::string revisited;
  progress_.on_line = [&](const std::string& text) {
    if (text.rfind("[second pass 1,", 0) != 0) return;
    const std::size_t name = text.find("] ") + 2;
    revisited = text.substr(name, text.find(' ', name) - name);
    const std::size_t end = text.find(" rounds, ");
    const std::size_t begin = text.rfind("  ", end) + 2;
    rounds_at_signal = std::stoul(text.substr(begin, end - begin));
    request_interrupt(SIGINT);
  };
  struct Forget {
    ~Forget() { clear_interrupt_for_testing(); }
  } forget;
  std::string message;
  try {
    compare(base, head);
    FAIL() << "the interrupt was not acted on";
  } catch (const Interrupted& stop) {
    EXPECT_EQ(stop.signal(), SIGINT);
    message = stop.what();
  }
  EXPECT_EQ(progress_.lines_with("[second pass ").size(), 1u) << "no visit after the signal";
  const std::size_t from = message.find("kept 2 of 2 scenes in ");
  ASSERT_NE(from, std::string::npos) << message;
  const std::size_t path_begin = from + std::string("kept 2 of 2 scenes in ").size();
  const std::size_t path_end = message.find(" (complete: false)", path_begin);
  ASSERT_NE(path_end, std::string::npos) << message;
  const ResultsDocument document = read_results(message.substr(path_begin, path_end - path_begin));
  EXPECT_FALSE(document.complete);
  ASSERT_GT(rounds_at_signal, 0u);
  const auto scene = std::find_if(document.scenes.begin(), document.scenes.end(),
                                  [&](const SceneResult& s) { return s.entry.id == revisited; });
  ASSERT_NE(scene, document.scenes.end()) << revisited;
  EXPECT_EQ(scene->runs.rounds.size(), rounds_at_signal) << "the visit's rounds are kept";
}

TEST_F(ComparePipelineTest, OpensWithWhatItCompares) {
  const std::string base = commit_tracer("2.0", "base");
  const std::string head = commit_tracer("2.0", "head");
  compare(base, head);
  ASSERT_FALSE(progress_.lines.empty());
  EXPECT_EQ(progress_.lines.front().rfind("comparing fake-cost-tracer " + base.substr(0, 7), 0), 0u)
      << progress_.lines.front();
  EXPECT_EQ(progress_.lines_with("(base) with").size(), 1u);
}

}  // namespace
}  // namespace raygate::testing

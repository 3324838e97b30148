// The scheduler of one scene (measure_scene) driven by a fake process table and a fake clock:
// warm-ups, rotating order, stop rules, failures, the duet schedule, and first_run.
#include "runner/scheduler.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fstream>
#include <thread>
#include <map>
#include <utility>

#include "core/error.h"
#include "core/fs.h"
#include "pipeline/stop_rules.h"
#include "fake_executor.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;
using testing::Call;
using testing::exited_with;
using testing::FakeClock;
using testing::FakeExecutor;
using testing::killed_by;

// Runs "<role>" and is timed by the process's wall seconds.
class FakeContender final : public Contender {
 public:
  using Contender::Contender;

  ProcessSpec command(const SceneInput& /*scene*/, const fs::path& run_dir) const override {
    ProcessSpec spec;
    spec.argv = {name()};
    spec.stdout_path = run_dir / "log.txt";
    return spec;
  }

  RunRecord interpret(const SceneInput& /*scene*/, const ProcessResult& result,
                      const ProcessSpec& spec, const fs::path& run_dir) const override {
    RunRecord run = record_process(result, spec);
    run.image = run_dir / "image.png";
    if (run.ok) run.seconds = run.wall_seconds;
    return run;
  }
};

// Stops (as a round budget would) once `rounds` rounds are complete.
StopRule stop_after(std::size_t rounds) {
  return [rounds](const std::vector<Round>& done, double /*seconds*/) {
    return done.size() >= rounds ? StopDecision::stop_budget_rounds
                                 : StopDecision::continue_measuring;
  };
}

class SchedulerTest : public ::testing::Test {
 protected:
  SceneRuns measure(const std::vector<const Contender*>& contenders, const StopRule& stop,
                    const RoundObserver& observer = {}) {
    return measure_scene(scene_, contenders, options_, stop, executor_, clock_,
                         dir_.path() / "scene", observer);
  }
  SceneRuns measure_pair(const StopRule& stop) { return measure({&baseline_, &tracer_}, stop); }

  TempDir dir_;
  FakeClock clock_;
  FakeExecutor executor_{clock_};
  ScheduleOptions options_;
  SceneInput scene_{SuiteScene{"balls", "balls", 1, 32, 32}, "balls.nff", {}, {}};
  FakeContender baseline_{Role::baseline};
  FakeContender tracer_{Role::tracer};
  FakeContender base_{Role::base};
  FakeContender head_{Role::head};
};

using Roles = std::vector<std::string>;

// --- order -------------------------------------------------------------------------------------

TEST_F(SchedulerTest, WarmupsRunFirstAndAreNotCountedAsRounds) {
  options_.warmup_runs = 2;
  const SceneRuns runs = measure_pair(stop_after(1));
  EXPECT_EQ(executor_.roles(), (Roles{"baseline", "tracer", "baseline", "tracer",  // warm-ups
                                      "baseline", "tracer"}));
  EXPECT_EQ(runs.warmup.at("baseline").size(), 2u);
  EXPECT_EQ(runs.warmup.at("tracer").size(), 2u);
  ASSERT_EQ(runs.rounds.size(), 1u);
  EXPECT_NE(runs.warmup.at("tracer")[1].log.string().find("warmup-2"), std::string::npos);
}

TEST_F(SchedulerTest, NoWarmupWhenAskedForNone) {
  options_.warmup_runs = 0;
  const SceneRuns runs = measure_pair(stop_after(1));
  EXPECT_TRUE(runs.warmup.empty());
  EXPECT_EQ(executor_.roles(), (Roles{"baseline", "tracer"}));
}

TEST_F(SchedulerTest, OrderAlternatesFromRoundToRound) {
  options_.warmup_runs = 0;
  const SceneRuns runs = measure_pair(stop_after(4));
  ASSERT_EQ(runs.rounds.size(), 4u);
  EXPECT_EQ(runs.rounds[0].order, (Roles{"baseline", "tracer"}));
  EXPECT_EQ(runs.rounds[1].order, (Roles{"tracer", "baseline"}));
  EXPECT_EQ(runs.rounds[2].order, (Roles{"baseline", "tracer"}));
  EXPECT_EQ(runs.rounds[3].order, (Roles{"tracer", "baseline"}));
  // The order recorded is the order the processes really ran in.
  EXPECT_EQ(executor_.roles(), (Roles{"baseline", "tracer", "tracer", "baseline", "baseline",
                                      "tracer", "tracer", "baseline"}));
}

TEST_F(SchedulerTest, OrderRotatesWithThreeContenders) {
  options_.warmup_runs = 1;
  const SceneRuns runs = measure({&baseline_, &base_, &head_}, stop_after(4));
  ASSERT_EQ(runs.rounds.size(), 4u);
  EXPECT_EQ(runs.rounds[0].order, (Roles{"baseline", "base", "head"}));
  EXPECT_EQ(runs.rounds[1].order, (Roles{"base", "head", "baseline"}));
  EXPECT_EQ(runs.rounds[2].order, (Roles{"head", "baseline", "base"}));
  EXPECT_EQ(runs.rounds[3].order, (Roles{"baseline", "base", "head"}));
  EXPECT_EQ(runs.warmup.size(), 3u);
}

TEST_F(SchedulerTest, EveryRoundHoldsEveryContendersRun) {
  executor_.set_seconds("baseline", {2.0});
  executor_.set_seconds("tracer", {0.5});
  const SceneRuns runs = measure_pair(stop_after(3));
  for (const Round& round : runs.rounds) {
    ASSERT_EQ(round.runs.size(), 2u);
    EXPECT_DOUBLE_EQ(round.runs.at("baseline").seconds, 2.0);
    EXPECT_DOUBLE_EQ(round.runs.at("tracer").seconds, 0.5);
  }
}

TEST_F(SchedulerTest, RunDirectoriesNameRoleAndRound) {
  const SceneRuns runs = measure_pair(stop_after(2));
  const fs::path scene_dir = dir_.path() / "scene";
  EXPECT_EQ(runs.warmup.at("tracer")[0].log, scene_dir / "tracer" / "warmup-1" / "log.txt");
  EXPECT_EQ(runs.rounds[1].runs.at("baseline").log,
            scene_dir / "baseline" / "round-002" / "log.txt");
  EXPECT_TRUE(fs::is_directory(scene_dir / "tracer" / "round-002"));
}

TEST_F(SchedulerTest, PinCpusApplyToEveryRunOfTheAlternateSchedule) {
  options_.pin_cpus = {3};
  measure_pair(stop_after(2));
  for (const Call& call : executor_.calls()) EXPECT_EQ(call.cpus, std::vector<int>{3}) << call.role;
}

TEST_F(SchedulerTest, RoundCpusPinEveryRunOfARoundToOneCpuChangingEverySecondRound) {
  options_.warmup_runs = 1;
  options_.round_cpus = {0, 1};
  const SceneRuns runs = measure_pair(stop_after(5));
  ASSERT_EQ(runs.rounds.size(), 5u);
  const std::vector<Call>& calls = executor_.calls();
  ASSERT_EQ(calls.size(), 12u);  // two warm-ups, then five rounds of two
  // Warm-ups on the first round's CPU; then rounds 1-2 on CPU 0, 3-4 on CPU 1, 5 on CPU 0: each
  // CPU sees both orders, and the two runs of a round always share their CPU.
  const std::vector<int> expected{0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 0, 0};
  for (std::size_t i = 0; i < calls.size(); ++i) {
    EXPECT_EQ(calls[i].cpus, std::vector<int>{expected[i]}) << "call " << i;
  }
}

TEST_F(SchedulerTest, PinCpusWinOverRoundCpus) {
  options_.pin_cpus = {3};
  options_.round_cpus = {0, 1};
  measure_pair(stop_after(4));
  for (const Call& call : executor_.calls()) EXPECT_EQ(call.cpus, std::vector<int>{3}) << call.role;
}

TEST_F(SchedulerTest, NormalizerJoinsOnlyTheFirstRoundsAndTheOthersStillAlternate) {
  options_.warmup_runs = 1;
  options_.normalizer_rounds = 2;
  const SceneRuns runs = measure({&baseline_, &base_, &head_}, stop_after(5));
  ASSERT_EQ(runs.rounds.size(), 5u);
  EXPECT_EQ(runs.rounds[0].order, (Roles{"baseline", "base", "head"}));
  EXPECT_EQ(runs.rounds[1].order, (Roles{"base", "head", "baseline"}));
  EXPECT_EQ(runs.rounds[2].order, (Roles{"base", "head"}));
  EXPECT_EQ(runs.rounds[3].order, (Roles{"head", "base"}));
  EXPECT_EQ(runs.rounds[4].order, (Roles{"base", "head"}));
  EXPECT_FALSE(runs.rounds[2].runs.contains("baseline"));
  EXPECT_EQ(runs.warmup.size(), 3u);  // the baseline still warms up once
  // 3 warm-ups + 2 rounds of three + 3 rounds of two.
  EXPECT_EQ(executor_.calls().size(), 3u + 6u + 6u);
}

TEST_F(SchedulerTest, RepeatsRunEveryContenderInterleavedAndKeepItsFastestRun) {
  options_.warmup_runs = 0;
  options_.normalizer_rounds = 1;
  options_.repeats = 2;
  executor_.set_seconds("baseline", {2.0, 1.5});
  executor_.set_seconds("base", {1.0, 0.8, 0.9, 0.7});
  executor_.set_seconds("head", {1.2});
  const SceneRuns runs = measure({&baseline_, &base_, &head_}, stop_after(2));
  ASSERT_EQ(runs.rounds.size(), 2u);
  // The baseline repeats too while it joins, so no ratio compares a fastest-of-two with one run.
  EXPECT_EQ(runs.rounds[0].order, (Roles{"baseline", "base", "head", "baseline", "base", "head"}));
  EXPECT_EQ(runs.rounds[1].order, (Roles{"head", "base", "head", "base"}));
  // No program runs twice in a row, so a slow spell two runs long cannot slow both of one
  // program's runs, and the fastest of each stays clean.
  for (const auto& round : runs.rounds) {
    for (std::size_t i = 1; i < round.order.size(); ++i) {
      EXPECT_NE(round.order[i], round.order[i - 1]);
    }
  }
  EXPECT_DOUBLE_EQ(runs.rounds[0].runs.at("baseline").seconds, 1.5);
  EXPECT_DOUBLE_EQ(runs.rounds[0].runs.at("base").seconds, 0.8);
  EXPECT_DOUBLE_EQ(runs.rounds[1].runs.at("base").seconds, 0.7);
  EXPECT_DOUBLE_EQ(runs.rounds[1].runs.at("head").seconds, 1.2);
  EXPECT_EQ(executor_.calls().size(), 6u + 4u);
  // Each repeat has its own run directory: the kept run is the one whose files are named.
  EXPECT_NE(runs.rounds[0].runs.at("baseline").log.string().find("round-001-2"), std::string::npos);
  EXPECT_NE(runs.rounds[0].runs.at("base").log.string().find("round-001-2"), std::string::npos);
  // A tie keeps the first.
  EXPECT_NE(runs.rounds[0].runs.at("head").log.string().find("round-001/"), std::string::npos);
  // A scene's line says how its rounds ran.
  EXPECT_EQ(runs_per_contender(runs.rounds[1]), 2u);
  EXPECT_EQ(repeats_note(runs.rounds), "each the fastest of 2 runs");
  std::vector<Round> mixed = runs.rounds;
  mixed.push_back(Round{{"base", "head"}, {}});
  EXPECT_EQ(runs_per_contender(mixed.back()), 1u);
  EXPECT_EQ(repeats_note(mixed), "2 of them the fastest of 2 runs");
  EXPECT_EQ(repeats_note({mixed.back()}), "");
  // A stored document's order may be any length; counted in one pass (a report of such a
  // document once took a quadratic count).
  Round claimed;
  for (int k = 0; k < 100000; ++k) claimed.order.insert(claimed.order.end(), {"base", "head"});
  EXPECT_EQ(runs_per_contender(claimed), 100000u);
}

// A RepeatChooser (ScheduleOptions::repeats_from_rounds): asked before every round with the
// rounds before it only, and the round runs each contender that many times.
TEST_F(SchedulerTest, EachRoundsRepeatsAreChosenFromTheRoundsBeforeIt) {
  options_.warmup_runs = 1;
  std::vector<std::size_t> asked_with;
  options_.repeats_from_rounds = [&](const SceneRuns& so_far) -> std::size_t {
    asked_with.push_back(so_far.rounds.size());
    return so_far.rounds.size() >= 2 ? 2 : 1;
  };
  executor_.set_seconds("tracer", {1.0, 0.9, 1.1, 0.8, 1.3, 0.7});
  const SceneRuns runs = measure_pair(stop_after(4));
  ASSERT_EQ(runs.rounds.size(), 4u);
  EXPECT_EQ(asked_with, (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(runs_per_contender(runs.rounds[1]), 1u);
  EXPECT_EQ(runs_per_contender(runs.rounds[2]), 2u);
  EXPECT_EQ(runs.rounds[3].order, (Roles{"tracer", "baseline", "tracer", "baseline"}));
  EXPECT_EQ(repeats_note(runs.rounds), "2 of them the fastest of 2 runs");
  // 2 warm-ups, 2 rounds of two runs, 2 rounds of four.
  EXPECT_EQ(executor_.calls().size(), 2u + 4u + 8u);
  options_.repeats_from_rounds = [](const SceneRuns&) -> std::size_t { return 0; };
  EXPECT_THROW(measure_pair(stop_after(1)), std::logic_error);
}

TEST_F(SchedulerTest, RepeatsAreForTheAlternateScheduleOnly) {
  options_.kind = ScheduleKind::duet;
  options_.repeats = 2;
  EXPECT_THROW(measure_pair(stop_after(1)), UsageError);
  options_.repeats = 1;
  options_.repeats_from_rounds = [](const SceneRuns&) -> std::size_t { return 2; };
  EXPECT_THROW(measure_pair(stop_after(1)), UsageError);
  options_.repeats_from_rounds = nullptr;
  options_.kind = ScheduleKind::alternate;
  options_.repeats = 0;
  EXPECT_THROW(measure_pair(stop_after(1)), UsageError);
}

TEST_F(SchedulerTest, SamplesOfRoundsWithoutTheNormalizer) {
  options_.warmup_runs = 0;
  options_.normalizer_rounds = 1;
  executor_.set_seconds("baseline", {2.0});
  executor_.set_seconds("base", {0.5});
  executor_.set_seconds("head", {0.6});
  const SceneRuns runs = measure({&baseline_, &base_, &head_}, stop_after(3));
  // The ratios pair only the round with a baseline; the change sees every round.
  EXPECT_EQ(round_samples(runs.rounds, Role::head).size(), 1u);
  const std::vector<CompareRound> samples = compare_samples(runs.rounds);
  ASSERT_EQ(samples.size(), 3u);
  EXPECT_EQ(samples[0].baseline_seconds, std::optional<double>(2.0));
  EXPECT_FALSE(samples[1].baseline_seconds.has_value());
  EXPECT_DOUBLE_EQ(samples[2].head_seconds, 0.6);
}

// --- stopping ----------------------------------------------------------------------------------

TEST_F(SchedulerTest, StopRuleSeesCompleteRoundsAndTheSecondsSpent) {
  executor_.set_seconds("baseline", {2.0});
  executor_.set_seconds("tracer", {1.0});
  std::vector<std::pair<std::size_t, double>> seen;
  const StopRule rule = [&](const std::vector<Round>& rounds, double seconds) {
    seen.emplace_back(rounds.size(), seconds);
    return rounds.size() == 3 ? StopDecision::stop_budget_time : StopDecision::continue_measuring;
  };
  const SceneRuns runs = measure_pair(rule);
  // One warm-up each (3 s), then 3 s per round: the warm-ups count against the time budget.
  const std::vector<std::pair<std::size_t, double>> expected{{1, 6.0}, {2, 9.0}, {3, 12.0}};
  EXPECT_EQ(seen, expected);
  EXPECT_EQ(runs.stop_reason, "stop_budget_time");
  EXPECT_DOUBLE_EQ(runs.seconds_spent, 12.0);
  EXPECT_FALSE(runs.failed());
}

TEST_F(SchedulerTest, AContinuedSceneSkipsTheWarmupsAndCarriesOnItsRoundsAndSeconds) {
  options_.warmup_runs = 1;
  options_.normalizer_rounds = 2;
  options_.round_cpus = {0, 1};
  executor_.set_seconds("baseline", {2.0});
  executor_.set_seconds("base", {1.0});
  executor_.set_seconds("head", {1.0});
  const std::vector<const Contender*> three{&baseline_, &base_, &head_};
  SceneRuns first = measure(three, stop_after(3));
  // 3 warm-ups (4 s), 2 rounds with the baseline (4 s each), 1 without (2 s).
  ASSERT_DOUBLE_EQ(first.seconds_spent, 14.0);
  const std::size_t calls_before = executor_.calls().size();

  std::vector<std::pair<std::size_t, double>> seen;
  const StopRule rule = [&](const std::vector<Round>& rounds, double seconds) {
    seen.emplace_back(rounds.size(), seconds);
    return rounds.size() == 5 ? StopDecision::stop_converged : StopDecision::continue_measuring;
  };
  const SceneRuns runs = continue_scene(scene_, three, options_, rule, executor_, clock_,
                                        dir_.path() / "scene", std::move(first));
  // No warm-ups again, no baseline (past its 2 rounds); the rotation goes on from round 4.
  ASSERT_EQ(runs.rounds.size(), 5u);
  EXPECT_EQ(executor_.calls().size(), calls_before + 4u);
  EXPECT_EQ(runs.rounds[3].order, (Roles{"head", "base"}));
  EXPECT_EQ(runs.rounds[4].order, (Roles{"base", "head"}));
  // Rounds 4 and 5 alternate CPUs as a first visit would have: rounds 2k, 2k+1 share a CPU.
  EXPECT_EQ(executor_.calls()[calls_before].cpus, std::vector<int>{1});
  EXPECT_EQ(executor_.calls()[calls_before + 2].cpus, std::vector<int>{0});
  EXPECT_NE(runs.rounds[4].runs.at("head").log.string().find("round-005"), std::string::npos);
  // The stop rule and the document see the seconds of both visits.
  const std::vector<std::pair<std::size_t, double>> expected{{4, 16.0}, {5, 18.0}};
  EXPECT_EQ(seen, expected);
  EXPECT_DOUBLE_EQ(runs.seconds_spent, 18.0);
  EXPECT_EQ(runs.stop_reason, "stop_converged");
  EXPECT_EQ(runs.warmup.size(), 3u);  // the first visit's warm-ups are kept
}

TEST_F(SchedulerTest, OnlyASceneMeasuredWithoutFailureContinues) {
  const std::vector<const Contender*> pair{&baseline_, &tracer_};
  EXPECT_THROW(continue_scene(scene_, pair, options_, stop_after(2), executor_, clock_,
                              dir_.path() / "scene", SceneRuns{}),
               std::invalid_argument);
  executor_.script("tracer", 2, killed_by(SIGSEGV));  // its warm-up runs, its first round crashes
  SceneRuns failed = measure_pair(stop_after(2));
  ASSERT_TRUE(failed.failed());
  EXPECT_THROW(continue_scene(scene_, pair, options_, stop_after(2), executor_, clock_,
                              dir_.path() / "scene", std::move(failed)),
               std::invalid_argument);
}

TEST_F(SchedulerTest, ObserverSeesEveryRoundBeforeTheStopRule) {
  std::vector<std::size_t> observed;
  const RoundObserver observer = [&](const std::vector<Round>& rounds, double /*seconds*/) {
    observed.push_back(rounds.size());
  };
  measure({&baseline_, &tracer_}, stop_after(3), observer);
  EXPECT_EQ(observed, (std::vector<std::size_t>{1, 2, 3}));
}

TEST_F(SchedulerTest, RatioStopRuleConvergesAtMinRoundsOnConstantTimes) {
  executor_.set_seconds("baseline", {2.0});
  executor_.set_seconds("tracer", {1.0});
  StoppingPolicy policy;
  policy.min_rounds = 4;
  const SceneRuns runs = measure_pair(ratio_stop_rule(policy, Role::tracer));
  EXPECT_EQ(runs.rounds.size(), 4u);
  EXPECT_EQ(runs.stop_reason, "stop_converged");
}

TEST_F(SchedulerTest, RatioStopRuleStopsAtTheRoundBudgetOnNoisyTimes) {
  executor_.set_seconds("baseline", {1.0, 1.3, 0.8, 1.1, 0.9});
  executor_.set_seconds("tracer", {0.5, 0.9, 0.6, 0.4, 0.7, 0.8});
  StoppingPolicy policy;
  policy.min_rounds = 3;
  policy.max_rounds = 7;
  const SceneRuns runs = measure_pair(ratio_stop_rule(policy, Role::tracer));
  EXPECT_EQ(runs.rounds.size(), 7u);
  EXPECT_EQ(runs.stop_reason, "stop_budget_rounds");
}

TEST_F(SchedulerTest, RatioStopRuleNeverCallsASingleRoundConverged) {
  StoppingPolicy policy;
  policy.min_rounds = 1;  // what --max-rounds 1 leaves
  policy.max_rounds = 1;
  const SceneRuns runs = measure_pair(ratio_stop_rule(policy, Role::tracer));
  EXPECT_EQ(runs.rounds.size(), 1u);
  EXPECT_EQ(runs.stop_reason, "stop_budget_rounds");
}

TEST_F(SchedulerTest, RatioStopRuleStopsAtTheTimeBudget) {
  executor_.set_seconds("baseline", {1.0, 1.3, 0.8, 1.1, 0.9});
  executor_.set_seconds("tracer", {0.5, 0.9, 0.6, 0.4, 0.7, 0.8});
  StoppingPolicy policy;
  policy.max_seconds = 10.0;  // warm-ups ~1.5 s, rounds ~1.7 s each
  const SceneRuns runs = measure_pair(ratio_stop_rule(policy, Role::tracer));
  EXPECT_EQ(runs.stop_reason, "stop_budget_time");
  EXPECT_GE(runs.seconds_spent, 10.0);
  EXPECT_LT(runs.seconds_spent - 10.0, 2.5);  // stopped in the round that crossed the budget
}

TEST(RoundSamples, PairTheTracerWithTheBaselineOfTheSameRound) {
  std::vector<Round> rounds(2);
  rounds[0].runs["baseline"].seconds = 2.0;
  rounds[0].runs["tracer"].seconds = 1.0;
  rounds[1].runs["baseline"].seconds = 4.0;
  rounds[1].runs["tracer"].seconds = 3.0;
  const std::vector<RoundSample> samples = round_samples(rounds, Role::tracer);
  ASSERT_EQ(samples.size(), 2u);
  EXPECT_DOUBLE_EQ(samples[1].tracer_seconds, 3.0);
  EXPECT_DOUBLE_EQ(samples[1].baseline_seconds, 4.0);
}

// --- failures ----------------------------------------------------------------------------------

// A sweep's tracer appended spheres to its scene after each render: the baseline was timed on a
// growing scene and the run passed. The run that changed the file fails the scene.
TEST_F(SchedulerTest, ARunThatWritesItsSceneFileFailsTheScene) {
  const fs::path nff = dir_.path() / "balls.nff";
  write_file_atomically(nff, "s 0 0 0 1\n");
  scene_.nff = nff;
  scene_.files[SceneFormat::nff] = nff;
  scene_.prepared_stamps[nff] = *file_stamp(nff);
  int tracer_runs = 0;
  executor_.on_success([&](const ProcessSpec& spec) {
    if (spec.argv.front() == "tracer" && ++tracer_runs == 3) {
      write_file_atomically(nff, "s 0 0 0 1\ns 1 1 1 1\n");
    }
  });
  const SceneRuns runs = measure_pair(stop_after(10));
  ASSERT_TRUE(runs.failed());
  EXPECT_EQ(runs.failed_role, Role::tracer);
  EXPECT_NE(
      runs.failed_run->failure.find("the scene file " + nff.string() + " changed while it ran"),
      std::string::npos)
      << runs.failed_run->failure;
  EXPECT_EQ(runs.rounds.size(), 1u);  // warm-up, round 1, then round 2's tracer changed it
}

// The stamp is one stat, not a hash: a write in place of the same size, its modification time
// set back, still moves the status-change time, which no process can set.
TEST_F(SchedulerTest, ASceneWrittenInPlaceWithItsTimeSetBackIsStillSeen) {
  const fs::path nff = dir_.path() / "balls.nff";
  write_file_atomically(nff, "s 0 0 0 1\n");
  const FileStamp prepared = *file_stamp(nff);
  const auto modified = fs::last_write_time(nff);
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  {
    std::ofstream same_size(nff, std::ios::in | std::ios::out);
    same_size << "s 0 0 0 2\n";
  }
  fs::last_write_time(nff, modified);
  EXPECT_EQ(file_stamp(nff)->size, prepared.size);
  EXPECT_EQ(file_stamp(nff)->modified_ns, prepared.modified_ns);
  EXPECT_NE(*file_stamp(nff), prepared);
}

TEST_F(SchedulerTest, CrashStopsTheSceneAndKeepsTheRoundsBefore) {
  executor_.script("tracer", 4, killed_by(SIGSEGV));  // warm-up, rounds 1-2, then round 3
  const SceneRuns runs = measure_pair(stop_after(10));
  ASSERT_TRUE(runs.failed());
  EXPECT_EQ(runs.failed_role, Role::tracer);
  EXPECT_EQ(runs.stop_reason, "failed");
  EXPECT_EQ(runs.rounds.size(), 2u);  // the incomplete third round is not kept
  EXPECT_FALSE(runs.failed_run->ok);
  EXPECT_NE(runs.failed_run->outcome.find("signal 11"), std::string::npos)
      << runs.failed_run->outcome;
  EXPECT_NE(runs.failed_run->failure.find("tracer killed by signal"), std::string::npos)
      << runs.failed_run->failure;
  EXPECT_EQ(runs.failed_run->log, dir_.path() / "scene" / "tracer" / "round-003" / "log.txt");
  // Round 3 ran the baseline, then the tracer crashed, and nothing ran after it.
  EXPECT_EQ(executor_.calls().size(), 2u + 4u + 2u);
  EXPECT_EQ(executor_.calls().back().role, "tracer");
}

TEST_F(SchedulerTest, NonZeroExitIsAFailureOfThatRole) {
  executor_.script("baseline", 3, exited_with(2, 0.1));
  const SceneRuns runs = measure_pair(stop_after(10));
  ASSERT_TRUE(runs.failed());
  EXPECT_EQ(runs.failed_role, Role::baseline);
  EXPECT_EQ(runs.failed_run->outcome, "exited with status 2");
  EXPECT_EQ(runs.rounds.size(), 1u);
  EXPECT_GT(runs.seconds_spent, 0.0);
}

TEST_F(SchedulerTest, FailureInWarmupLeavesNoRounds) {
  executor_.script("tracer", 1, killed_by(SIGABRT));
  const SceneRuns runs = measure_pair(stop_after(10));
  ASSERT_TRUE(runs.failed());
  EXPECT_EQ(runs.failed_role, Role::tracer);
  EXPECT_TRUE(runs.rounds.empty());
  ASSERT_EQ(runs.warmup.at("tracer").size(), 1u);
  EXPECT_FALSE(runs.warmup.at("tracer")[0].ok);
  EXPECT_EQ(executor_.roles(), (Roles{"baseline", "tracer"}));
  EXPECT_EQ(runs.first_run(Role::tracer), nullptr);
}

TEST_F(SchedulerTest, StopRuleIsNotAskedAfterAFailure) {
  executor_.script("tracer", 2, killed_by(SIGKILL));
  int asked = 0;
  const SceneRuns runs = measure_pair([&](const std::vector<Round>&, double) {
    ++asked;
    return StopDecision::continue_measuring;
  });
  EXPECT_TRUE(runs.failed());
  EXPECT_EQ(asked, 0);
}

TEST_F(SchedulerTest, SuccessInNoMeasurableTimeIsAFailureOfThatSceneOnly) {
  executor_.script("tracer", 3, exited_with(0, 0.0));  // round 2
  StoppingPolicy policy;
  policy.min_rounds = 2;
  SceneRuns runs;
  EXPECT_NO_THROW(runs = measure_pair(ratio_stop_rule(policy, Role::tracer)));
  ASSERT_TRUE(runs.failed());
  EXPECT_EQ(runs.failed_role, Role::tracer);
  EXPECT_EQ(runs.failed_run->failure,
            "tracer run took 0 s by its timing metric; a ratio needs a "
            "positive time");
  EXPECT_EQ(runs.rounds.size(), 1u);
}

// --- duet --------------------------------------------------------------------------------------

class DuetTest : public SchedulerTest {
 protected:
  void SetUp() override {
    options_.kind = ScheduleKind::duet;
    options_.warmup_runs = 0;
    options_.duet_cpus = {2, 5};
  }
};

TEST_F(DuetTest, ContendersOfARoundStartTogether) {
  measure_pair(stop_after(3));
  const std::vector<Call>& calls = executor_.calls();
  ASSERT_EQ(calls.size(), 6u);
  for (std::size_t i = 0; i < calls.size(); i += 2) {
    EXPECT_EQ(calls[i].batch, calls[i + 1].batch) << "round " << i / 2 + 1;
    EXPECT_NE(calls[i].role, calls[i + 1].role);
  }
  EXPECT_NE(calls[0].batch, calls[2].batch);
}

TEST_F(DuetTest, EachContenderIsPinnedToItsOwnCpuAndTheCpusSwapEachRound) {
  const SceneRuns runs = measure_pair(stop_after(3));
  std::map<std::string, std::vector<std::vector<int>>> cpus;  // role -> per round
  for (const Call& call : executor_.calls()) cpus[call.role].push_back(call.cpus);
  using Cpus = std::vector<std::vector<int>>;
  EXPECT_EQ(cpus["baseline"], (Cpus{{2}, {5}, {2}}));
  EXPECT_EQ(cpus["tracer"], (Cpus{{5}, {2}, {5}}));
  // The order names who had the first duet CPU, then the second.
  EXPECT_EQ(runs.rounds[0].order, (Roles{"baseline", "tracer"}));
  EXPECT_EQ(runs.rounds[1].order, (Roles{"tracer", "baseline"}));
}

TEST_F(DuetTest, ElapsedTimeIsTheLongerRunOfEachRound) {
  executor_.set_seconds("baseline", {2.0});
  executor_.set_seconds("tracer", {3.0});
  const SceneRuns runs = measure_pair(stop_after(2));
  EXPECT_DOUBLE_EQ(runs.seconds_spent, 6.0);
  EXPECT_DOUBLE_EQ(runs.rounds[0].runs.at("tracer").seconds, 3.0);
}

TEST_F(DuetTest, WarmupsRunOneAtATimeBeforeTheDuets) {
  options_.warmup_runs = 1;
  const SceneRuns runs = measure_pair(stop_after(1));
  const std::vector<Call>& calls = executor_.calls();
  ASSERT_EQ(calls.size(), 4u);
  EXPECT_NE(calls[0].batch, calls[1].batch);
  EXPECT_EQ(calls[2].batch, calls[3].batch);
  EXPECT_EQ(runs.rounds.size(), 1u);
}

TEST_F(DuetTest, FailureOfEitherStopsTheSceneAndKeepsEarlierRounds) {
  executor_.script("tracer", 2, exited_with(1, 0.2));
  const SceneRuns runs = measure_pair(stop_after(5));
  ASSERT_TRUE(runs.failed());
  EXPECT_EQ(runs.failed_role, Role::tracer);
  EXPECT_EQ(runs.rounds.size(), 1u);
}

TEST_F(DuetTest, SuccessInNoMeasurableTimeFailsInADuetToo) {
  executor_.script("baseline", 2, exited_with(0, 0.0));
  const SceneRuns runs = measure_pair(stop_after(3));
  ASSERT_TRUE(runs.failed());
  EXPECT_EQ(runs.failed_role, Role::baseline);
  EXPECT_EQ(runs.rounds.size(), 1u);
  EXPECT_EQ(executor_.calls()[2].batch, executor_.calls()[3].batch);  // it was a duet round
}

TEST_F(DuetTest, ThreeContendersRunTheBaselineAloneThenBaseAndHeadTogether) {
  const SceneRuns runs = measure({&baseline_, &base_, &head_}, stop_after(2));
  const std::vector<Call>& calls = executor_.calls();
  ASSERT_EQ(calls.size(), 6u);
  for (std::size_t i = 0; i < calls.size(); i += 3) {
    EXPECT_EQ(calls[i].role, "baseline");
    EXPECT_NE(calls[i].batch, calls[i + 1].batch) << "the baseline runs alone";
    EXPECT_EQ(calls[i + 1].batch, calls[i + 2].batch) << "base and head start together";
  }
  using Cpus = std::vector<std::vector<int>>;
  std::map<std::string, Cpus> cpus;
  for (const Call& call : calls) cpus[call.role].push_back(call.cpus);
  EXPECT_EQ(cpus["baseline"], (Cpus{{2}, {5}}));  // the round's first CPU
  EXPECT_EQ(cpus["base"], (Cpus{{2}, {5}}));
  EXPECT_EQ(cpus["head"], (Cpus{{5}, {2}}));
  EXPECT_EQ(runs.rounds[0].order, (Roles{"baseline", "base", "head"}));
  EXPECT_EQ(runs.rounds[1].order, (Roles{"baseline", "head", "base"}));
  EXPECT_EQ(runs.rounds[1].runs.size(), 3u);
}

TEST_F(DuetTest, TheBaselineJoinsOnlyItsRoundsInADuetToo) {
  options_.warmup_runs = 0;
  options_.normalizer_rounds = 1;
  const SceneRuns runs = measure({&baseline_, &base_, &head_}, stop_after(3));
  ASSERT_EQ(runs.rounds.size(), 3u);
  EXPECT_TRUE(runs.rounds[0].runs.contains("baseline"));
  for (std::size_t i = 1; i < 3; ++i) {
    EXPECT_FALSE(runs.rounds[i].runs.contains("baseline")) << i;
    EXPECT_EQ(runs.rounds[i].runs.size(), 2u) << i;  // base and head, together
  }
}

TEST_F(DuetTest, ABaselineFailingAloneStopsTheSceneBeforeThePairStarts) {
  executor_.script("baseline", 1, killed_by(SIGSEGV));
  const SceneRuns runs = measure({&baseline_, &base_, &head_}, stop_after(3));
  ASSERT_TRUE(runs.failed());
  EXPECT_EQ(runs.failed_role, Role::baseline);
  EXPECT_EQ(executor_.calls().size(), 1u);
}

TEST_F(DuetTest, FourContendersAreAUsageError) {
  EXPECT_THROW(measure({&baseline_, &base_, &head_, &tracer_}, stop_after(1)), UsageError);
  EXPECT_TRUE(executor_.calls().empty());
}

TEST_F(DuetTest, TheSameCpuTwiceIsAUsageError) {
  options_.duet_cpus = {1, 1};
  EXPECT_THROW(measure_pair(stop_after(1)), UsageError);
}

// --- first_run ---------------------------------------------------------------------------------

TEST_F(SchedulerTest, FirstRunIsTheWarmupWhoseImageIsChecked) {
  const SceneRuns runs = measure_pair(stop_after(2));
  const RunRecord* first = runs.first_run(Role::tracer);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->image, dir_.path() / "scene" / "tracer" / "warmup-1" / "image.png");
}

TEST_F(SchedulerTest, FirstRunWithoutWarmupIsTheFirstRound) {
  options_.warmup_runs = 0;
  const SceneRuns runs = measure_pair(stop_after(2));
  const RunRecord* first = runs.first_run(Role::tracer);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->image, dir_.path() / "scene" / "tracer" / "round-001" / "image.png");
  EXPECT_EQ(runs.first_run(Role::head), nullptr);
}

// Without a warm-up, head crashing in round 1 comes after base ran in that round: that run is
// kept, so "base ran" (the gate's crash verdict) does not depend on the warm-up.
TEST_F(SchedulerTest, CrashWithoutWarmupKeepsTheRunsBeforeItInItsRound) {
  options_.warmup_runs = 0;
  executor_.script("head", 1, killed_by(SIGSEGV));
  const SceneRuns runs = measure({&baseline_, &base_, &head_}, stop_after(10));
  ASSERT_TRUE(runs.failed());
  EXPECT_EQ(runs.failed_role, Role::head);
  EXPECT_TRUE(runs.rounds.empty());
  EXPECT_EQ(runs.partial_round.size(), 2u);
  const RunRecord* base = runs.first_run(Role::base);
  ASSERT_NE(base, nullptr);
  EXPECT_EQ(base->image, dir_.path() / "scene" / "base" / "round-001" / "image.png");
  EXPECT_EQ(runs.first_run(Role::head), nullptr);
}

TEST_F(DuetTest, CrashKeepsTheOtherRunOfItsRound) {
  options_.warmup_runs = 0;
  executor_.script("tracer", 1, killed_by(SIGSEGV));
  const SceneRuns runs = measure_pair(stop_after(10));
  ASSERT_TRUE(runs.failed());
  EXPECT_EQ(runs.failed_role, Role::tracer);
  ASSERT_EQ(runs.partial_round.size(), 1u);
  EXPECT_NE(runs.first_run(Role::baseline), nullptr);
}

}  // namespace
}  // namespace raygate

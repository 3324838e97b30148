// The timing-mode registry (runner/timing/): every mode found by its name, the adapter's timing
// section mapped to its mode, --timing resolved against the adapter, and what each mode reads
// from a run.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "core/error.h"
#include "measure/stopping_policy.h"
#include "runner/timing/timing_modes.h"

namespace raygate {
namespace {

RunRecord run_with(double wall, double user, double system) {
  RunRecord run;
  run.ok = true;
  run.wall_seconds = wall;
  run.user_seconds = user;
  run.system_seconds = system;
  return run;
}

Timing adapter_timing(TimingSource source, TimingMetric metric = TimingMetric::wall) {
  Timing timing;
  timing.source = source;
  timing.metric = metric;
  return timing;
}

TEST(TimingModes, NamesAreUniqueAndEachModeIsFoundByItsName) {
  std::set<std::string> names;
  std::set<std::string> tracer_clocks;
  for (const TimingMode* mode : timing_modes()) {
    EXPECT_TRUE(names.insert(std::string(mode->name())).second) << mode->name();
    // Documents key history on the tracer's clock name: two modes must never share one.
    EXPECT_TRUE(tracer_clocks.insert(std::string(mode->tracer_clock())).second);
    EXPECT_EQ(&timing_mode(mode->name()), mode);
    EXPECT_FALSE(mode->description().empty());
  }
  EXPECT_GE(names.size(), 5u);
}

TEST(TimingModes, UnknownNameIsAUsageErrorListingTheModes) {
  try {
    (void)timing_mode("usr");
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("'usr'"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("user"), std::string::npos) << e.what();
  }
}

TEST(TimingModes, CommandLineOffersEveryModeButReported) {
  const std::vector<std::string> choices = timing_mode_choices();
  EXPECT_EQ(choices, (std::vector<std::string>{"wall", "cpu", "user", "sim"}));
}

TEST(TimingModes, EachProcessClockReadsItsOwnTime) {
  const RunRecord run = run_with(3.0, 1.25, 0.5);
  EXPECT_DOUBLE_EQ(*timing_mode("wall").seconds(run), 3.0);
  EXPECT_DOUBLE_EQ(*timing_mode("cpu").seconds(run), 1.75);
  EXPECT_DOUBLE_EQ(*timing_mode("user").seconds(run), 1.25);
  EXPECT_EQ(timing_mode("user").tracer_clock(), "process-user");
  EXPECT_EQ(timing_mode("user").baseline_clock(), "process-user");
}

TEST(TimingModes, ReportedAndSimulatedNeedTheirOwnNumbers) {
  RunRecord run = run_with(3.0, 1.25, 0.5);
  EXPECT_FALSE(timing_mode("reported").seconds(run));
  EXPECT_FALSE(timing_mode("sim").seconds(run));
  run.reported_seconds = 0.75;
  EXPECT_DOUBLE_EQ(*timing_mode("reported").seconds(run), 0.75);
  run.simulated = SimulatedCounters{};
  run.simulated->ir = 1000;
  EXPECT_DOUBLE_EQ(*timing_mode("sim").seconds(run), estimated_cycles(*run.simulated));
}

// "Exact" and "under cachegrind" are two questions: sim answers yes to both, every clock no;
// the unit is the mode's own.
TEST(TimingModes, ExactAndUnderCachegrindAreAskedApart) {
  for (const TimingMode* mode : timing_modes()) {
    const bool sim = mode->name() == "sim";
    EXPECT_EQ(mode->exact(), sim) << mode->name();
    EXPECT_EQ(mode->under_cachegrind(), sim) << mode->name();
    EXPECT_EQ(mode->unit(), sim ? "cycles" : "seconds") << mode->name();
  }
}

// A run timed by the tracer's reported seconds still records the process's: its start-up is
// the process wall time the reported time leaves out, a counter in seconds.
TEST(TimingModes, ReportedRecordsTheStartUpItLeavesOut) {
  const TimingMode& reported = timing_mode("reported");
  ASSERT_EQ(reported.counters().size(), 1u);
  EXPECT_EQ(reported.counters()[0].name, "startup_seconds");
  EXPECT_EQ(reported.counters()[0].unit, "seconds");
  RunRecord run = run_with(1.5, 1.25, 0.1);
  run.reported_seconds = 0.375;
  reported.collect(run, "unused");
  ASSERT_EQ(run.counters.count("startup_seconds"), 1u);
  EXPECT_DOUBLE_EQ(run.counters.at("startup_seconds").value, 1.125);
  EXPECT_EQ(run.counters.at("startup_seconds").unit, "seconds");
  // A render reported a little longer than its process (two clocks read apart): no start-up,
  // never a negative one.
  run.reported_seconds = 1.6;
  reported.collect(run, "unused");
  EXPECT_DOUBLE_EQ(run.counters.at("startup_seconds").value, 0.0);
  // Without a reported time nothing is derived; a process clock records nothing.
  RunRecord plain = run_with(1.5, 1.25, 0.1);
  reported.collect(plain, "unused");
  timing_mode("wall").collect(plain, "unused");
  EXPECT_TRUE(plain.counters.empty());
}

// Under cachegrind the metered peak is valgrind's (the tracer inside it several times over): kept
// in the record, not claimed as the tracer's own for the memory gate.
TEST(TimingModes, SimulatedRunsDoNotClaimValgrindsPeakAsTheTracers) {
  RunRecord run = run_with(1.5, 1.25, 0.1);
  run.max_rss_kib = 400000;
  run.max_rss_own = true;
  timing_mode("sim").collect(run, "no-cachegrind-files-here");
  EXPECT_FALSE(run.max_rss_own);
  EXPECT_EQ(run.max_rss_kib, 400000);
}

TEST(TimingModes, AdapterTimingMapsToItsMode) {
  EXPECT_EQ(adapter_timing_mode(adapter_timing(TimingSource::process)).name(), "wall");
  EXPECT_EQ(adapter_timing_mode(adapter_timing(TimingSource::process, TimingMetric::cpu)).name(),
            "cpu");
  EXPECT_EQ(adapter_timing_mode(adapter_timing(TimingSource::reported)).name(), "reported");
  EXPECT_EQ(adapter_timing_mode(adapter_timing(TimingSource::simulated)).name(), "sim");
}

// A clock chosen on the command line replaces the adapter's, whatever its source.
TEST(TimingModes, ChoiceResolvesAgainstTheAdapter) {
  const Timing process = adapter_timing(TimingSource::process, TimingMetric::cpu);
  const Timing reported = adapter_timing(TimingSource::reported);
  EXPECT_EQ(resolve_timing_mode(process, "").name(), "cpu");
  EXPECT_EQ(resolve_timing_mode(process, "user").name(), "user");
  EXPECT_EQ(resolve_timing_mode(process, "sim").name(), "sim");
  // Sweep 12: --timing user on a reporting adapter was dropped silently; the choice is the user's.
  EXPECT_EQ(resolve_timing_mode(reported, "user").name(), "user");
  EXPECT_EQ(resolve_timing_mode(reported, "").name(), "reported");
  EXPECT_EQ(resolve_timing_mode(reported, "sim").name(), "sim");
}

// Only sim changes the measurement; a clock leaves the plan as it was.
TEST(TimingModes, ProcessClocksPrepareNothing) {
  Suite suite;
  ScheduleOptions schedule;
  schedule.warmup_runs = 3;
  schedule.round_cpus = {0, 1};
  StoppingPolicy stopping;
  const std::filesystem::path file = "a.json";
  TimingPlan plan{suite, 1, file, schedule, stopping, {}, {}, {}};
  timing_mode("user").prepare(plan);
  EXPECT_EQ(schedule.warmup_runs, 3);
  EXPECT_EQ(schedule.round_cpus, (std::vector<int>{0, 1}));
  EXPECT_FALSE(plan.default_max_slowdown);
  EXPECT_FALSE(plan.cachegrind);
  EXPECT_TRUE(plan.warnings.empty());
}

}  // namespace
}  // namespace raygate

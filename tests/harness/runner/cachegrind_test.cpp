// Reading cachegrind's output: recorded files (tests/fixtures/cachegrind, trimmed real output of
// valgrind 3.19 with raygate's cache geometry), summed per run; damaged or incomplete output is
// an error naming file and line; the command line raygate builds; the baseline's cost cache.
#include "runner/cachegrind.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/fs.h"
#include "runner/baseline_cost_cache.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;
const fs::path kRecorded = fs::path(RAYGATE_SOURCE_DIR) / "tests" / "fixtures" / "cachegrind";

TEST(Cachegrind, ParsesTheSummaryOfARecordedFile) {
  const SimulatedCounters c = parse_cachegrind_output(read_file(kRecorded / "true.cg"), "true.cg");
  // summary: 131555 1091 1072 30123 1227 1022 10266 342 312
  EXPECT_EQ(c.ir, 131555u);
  EXPECT_EQ(c.i1mr, 1091u);
  EXPECT_EQ(c.ilmr, 1072u);
  EXPECT_EQ(c.dr, 30123u);
  EXPECT_EQ(c.d1mr, 1227u);
  EXPECT_EQ(c.dlmr, 1022u);
  EXPECT_EQ(c.dw, 10266u);
  EXPECT_EQ(c.d1mw, 342u);
  EXPECT_EQ(c.dlmw, 312u);
  EXPECT_EQ(c.processes, 1);
}

TEST(Cachegrind, EventsAreMatchedByNameNotPosition) {
  const SimulatedCounters c = parse_cachegrind_output(
      "events: DLmw Ir D1mw I1mr ILmr Dr D1mr DLmr Dw\nsummary: 9 1 8 2 3 4 5 6 7\n", "x");
  EXPECT_EQ(c.ir, 1u);
  EXPECT_EQ(c.dlmw, 9u);
  EXPECT_EQ(c.d1mw, 8u);
}

void expect_error(const std::string& text, const std::string& part) {
  try {
    parse_cachegrind_output(text, "out/cg.42");
    ADD_FAILURE() << "no error for: " << text;
  } catch (const InfraError& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(Cachegrind, DamagedOutputIsAnErrorWithFileAndLine) {
  const std::string events = "events: Ir I1mr ILmr Dr D1mr DLmr Dw D1mw DLmw\n";
  expect_error("cmd: x\n" + events, "out/cg.42: no 'summary:' line");
  expect_error("summary: 1 2 3\n", "no 'events:' line");
  expect_error("cmd: x\n" + events + "summary: 1 2 3\n", "out/cg.42:3: 3 counts for the 9 events");
  expect_error(events + "summary: 1 2 3 4 5 x 7 8 9\n", "out/cg.42:2: summary count 'x'");
  // Without --cache-sim=yes cachegrind counts instructions only.
  expect_error("events: Ir\nsummary: 100\n",
               "no 'I1mr' event (was cachegrind run with --cache-sim=yes?)");
}

TEST(Cachegrind, ARunsCountersAreTheSumOfItsProcesses) {
  TempDir dir("cachegrind-test");
  fs::copy_file(kRecorded / "true.cg", dir.path() / "cg.100");
  fs::copy_file(kRecorded / "echo.cg", dir.path() / "cg.101");
  write_file_atomically(dir.path() / "other.txt", "not cachegrind output");
  const SimulatedCounters total = read_cachegrind_outputs(dir.path());
  EXPECT_EQ(total.processes, 2);
  EXPECT_EQ(total.ir, 131555u + 309085u);  // echo.cg's summary: 309085 ...

  RunRecord run;
  run.ok = true;
  record_simulated_cost(run, dir.path());
  ASSERT_TRUE(run.simulated);
  EXPECT_DOUBLE_EQ(run.seconds, estimated_cycles(total));
}

TEST(Cachegrind, ARunWithoutOutputFails) {
  TempDir dir("cachegrind-test");
  EXPECT_THROW(read_cachegrind_outputs(dir.path()), InfraError);
  RunRecord run;
  run.ok = true;
  record_simulated_cost(run, dir.path());
  EXPECT_FALSE(run.ok);
  EXPECT_NE(run.failure.find("cachegrind wrote no output file in"), std::string::npos);
}

TEST(Cachegrind, CommandTracesChildrenWithAFixedCacheGeometry) {
  TempDir dir("cachegrind-test");
  ProcessSpec spec;
  spec.argv = {"/bin/sh", "wrapper.sh"};
  const ProcessSpec wrapped =
      under_cachegrind(spec, Cachegrind{"valgrind", "valgrind-3.19.0"}, dir.path() / "cg");
  const std::vector<std::string> expected = {
      "valgrind",
      "--tool=cachegrind",
      "--cache-sim=yes",
      "--branch-sim=no",
      "--trace-children=yes",
      "--I1=32768,8,64",
      "--D1=32768,8,64",
      "--LL=8388608,16,64",
      "--cachegrind-out-file=" + (dir.path() / "cg" / "cg.%p").string(),
      "/bin/sh",
      "wrapper.sh"};
  EXPECT_EQ(wrapped.argv, expected);
  EXPECT_TRUE(fs::is_directory(dir.path() / "cg"));
}

TEST(Cachegrind, DeterminismNoteNamesTheSpread) {
  SceneRuns runs;
  RunRecord a;
  a.ok = true;
  a.simulated = SimulatedCounters{};
  a.seconds = 1000.0;
  runs.rounds.push_back({{"baseline", "head"}, {{"baseline", a}, {"head", a}}});
  runs.rounds.push_back({{"head", "baseline"}, {{"baseline", a}, {"head", a}}});
  EXPECT_EQ(determinism_note(runs), "simulated cycles, counts repeat exactly");
  runs.rounds[1].runs["head"].seconds = 1001.0;
  EXPECT_EQ(determinism_note(runs),
            "simulated cycles repeat within 0.25% (spread: head 0.1%): counted");
  runs.rounds[1].runs["head"].seconds = 1003.0;
  EXPECT_EQ(determinism_note(runs),
            "simulated cycles differ between runs by more than 0.25% (spread: head 0.3%): timed "
            "statistics");
  EXPECT_EQ(determinism_note(SceneRuns{}), "");
}

BaselineCostKey key(const std::string& valgrind) {
  return {"abc", valgrind, "def", "center", "none"};
}

TEST(BaselineCostCache, KeepsACostOnlyOnceTwoRunsAgreed) {
  TempDir dir("cost-cache-test");
  SimulatedCounters cost;
  cost.ir = 12345;
  BaselineCostCache cache(dir.path());
  EXPECT_FALSE(cache.find(key("valgrind-3.19.0")));
  EXPECT_FALSE(cache.observe(key("valgrind-3.19.0"), cost));
  EXPECT_FALSE(cache.find(key("valgrind-3.19.0")));  // one run proves nothing
  EXPECT_TRUE(cache.observe(key("valgrind-3.19.0"), cost));
  // Another process (the next CI job) reads it; another valgrind does not.
  const BaselineCostCache next_job(dir.path());
  ASSERT_TRUE(next_job.find(key("valgrind-3.19.0")));
  EXPECT_EQ(*next_job.find(key("valgrind-3.19.0")), cost);
  EXPECT_FALSE(next_job.find(key("valgrind-3.20.0")));
}

TEST(BaselineCostCache, CountsThatDifferAreNeverCached) {
  TempDir dir("cost-cache-test");
  SimulatedCounters first, second;
  first.ir = 100;
  second.ir = 101;
  BaselineCostCache cache(dir.path());
  EXPECT_FALSE(cache.observe(key("v"), first));
  EXPECT_FALSE(cache.observe(key("v"), second));
  EXPECT_FALSE(cache.observe(key("v"), second));  // nor after they seem to settle
  EXPECT_FALSE(cache.find(key("v")));
}

TEST(BaselineCostCache, ADamagedEntryIsAMiss) {
  TempDir dir("cost-cache-test");
  BaselineCostCache cache(dir.path());
  write_file_atomically(dir.path() / (key("v").id() + ".json"), "{not json");
  EXPECT_FALSE(cache.find(key("v")));
}

}  // namespace
}  // namespace raygate

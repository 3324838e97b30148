// One yardstick for both sides (issue 18): a "tracer" that is a shell script running
// raygate-baseline itself does the baseline's very work, so its normalized ratio must be 1. Before
// the baseline was timed by the tracer's clock this ratio was 1.3-1.9 on the ci scenes (the
// baseline timed in-process, the tracer's process counting OpenImageIO's start-up).
//
// Which clock times each side is behaviour, and is tested exactly here in wall, CPU and reported
// timing: every baseline run's seconds are the reading of the tracer's clock. That the ratio is 1
// is tested where it is deterministic: under cachegrind (--timing sim), where a systematic
// difference between the two sides' yardsticks shows to a fraction of a percent on any machine.
// The timed ratio itself is measured, not asserted: bench/identity-ratio gives the figure. The
// timed tests keep only a gross bound (a unit or clock mix-up is off by 10x or more): the CI
// runner, a shared 2-core VM, once measured this very tracer at 0.72 and 1.60 in 9 rounds.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "checkout/git_fixture.h"
#include "cli_support.h"
#include "results/results.h"
#include "valgrind_baseline.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Timed: what a shared runner's noise cannot reach, but seconds taken for milliseconds, or one
// side's clock counting a sleep or start-up of seconds, would.
constexpr double kTimedLowest = 0.4;
constexpr double kTimedHighest = 2.5;
// Five rounds: a median of five runs a side stays inside the bound at this VM's ±30% per run
// (2026-11-29), and the three timed tests run alone (SERIAL), so each round is the suite's time.
constexpr const char* kTimedRounds = "5";
// Simulated: measured 0.998-0.999 on these 20 M-instruction scenes (the shell exec's itself away,
// and the baseline parses two options more); a yardstick that differs shows as a percent or more.
constexpr double kSimulatedTolerance = 0.01;

// Two scenes of about 0.2 s each for the baseline (--accel none): long enough that what the
// tracer does besides the baseline's work (start /bin/sh: about 4 ms of CPU at load 5 on this
// 2-core machine, measured) stays well inside the margin, short enough for a test. At 30 ms
// scenes, with PNG written as well, those extras alone made the ratio 1.3-1.8.
constexpr const char* kSuite = R"({
  "name": "identity",
  "description": "the identity tracer's test: two small scenes",
  "scenes": [
    {"id": "tetra", "scene": "tetra", "size": 5, "resolution": [128, 128]},
    {"id": "balls", "scene": "balls", "size": 3, "resolution": [128, 128]}
  ]
})";

// Under cachegrind each run costs about 30x its native time: one smaller scene of each kind.
constexpr const char* kSimulatedSuite = R"({
  "name": "identity-sim",
  "description": "the identity tracer's simulated test: two tiny scenes",
  "scenes": [
    {"id": "tetra", "scene": "tetra", "size": 3, "resolution": [48, 48]},
    {"id": "balls", "scene": "balls", "size": 1, "resolution": [48, 48]}
  ]
})";

class IdentityRatio : public ::testing::Test {
 protected:
  IdentityRatio() : repo_(dir_.path() / "identity-repo") {
    write_file_atomically(suite_, kSuite);
    write_file_atomically(simulated_suite_, kSimulatedSuite);
    fs::create_directories(dir_.path() / "no-goldens");
    repo_.write("identity.sh", "#!/bin/sh\nexec \"" + std::string(RAYGATE_BASELINE_EXE) +
                                   "\" \"$1\" -o \"$2\" $3\n");
    repo_.commit("the identity tracer");
  }

  // An adapter running identity.sh, timed by `timing`; `extra` is passed to the baseline.
  fs::path adapter(const std::string& name, const json& timing, const std::string& extra) const {
    // PPM, as the baseline writes during measurement: the same work, not PNG's extra deflate.
    json run = {"/bin/sh", "{src}/identity.sh", "{scene}", "{workdir}/identity.ppm"};
    if (!extra.empty()) run.push_back(extra);
    const json a = {{"name", name},
                    {"scene_format", "nff"},
                    {"run", run},
                    {"image", "{workdir}/identity.ppm"},
                    {"timing", timing}};
    const fs::path path = dir_.path() / (name + ".json");
    write_file_atomically(path, a.dump(2));
    return path;
  }

  ResultsDocument measure(const fs::path& adapter_file, const std::vector<std::string>& extra,
                          const fs::path& suite, const std::string& rounds) {
    const fs::path out =
        dir_.path() / (adapter_file.stem().string() + "-" + std::to_string(extra.size()) + ".json");
    std::vector<std::string> args{"run",
                                  "--repo",
                                  repo_.path().string(),
                                  "--adapter",
                                  adapter_file.string(),
                                  "--suite",
                                  suite.string(),
                                  "--cache-dir",
                                  (dir_.path() / "cache").string(),
                                  "--golden-dir",
                                  (dir_.path() / "no-goldens").string(),
                                  "--min-rounds",
                                  rounds,
                                  "--max-rounds",
                                  rounds,
                                  "--warmup",
                                  "1",
                                  "--no-store",
                                  "--out",
                                  out.string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const CliRun r = run_raygate(args, dir_);
    EXPECT_EQ(r.exit_code, 0) << r.out;
    return read_results(out);
  }

  ResultsDocument measure_timed(const fs::path& adapter_file,
                                const std::vector<std::string>& extra) {
    return measure(adapter_file, extra, suite_, kTimedRounds);
  }

  // Every scene's ratio within the gross bound, and each baseline run timed by `clock`.
  static void expect_identity(const ResultsDocument& d, const std::string& clock) {
    EXPECT_EQ(d.baseline.timing, clock);
    ASSERT_EQ(d.scenes.size(), 2u);
    for (const SceneResult& s : d.scenes) {
      SCOPED_TRACE("scene " + s.entry.id + ", baseline clock " + clock);
      const RatioSummary* r = s.ratio(Role::tracer);
      ASSERT_NE(r, nullptr);
      EXPECT_GE(r->ratio, kTimedLowest);
      EXPECT_LE(r->ratio, kTimedHighest);
      for (const Round& round : s.runs.rounds) {
        const RunRecord& baseline = round.runs.at("baseline");
        ASSERT_TRUE(baseline.reported_seconds);  // the in-process seconds, kept as extra data
        const double expected = clock == "process-wall"  ? baseline.wall_seconds
                                : clock == "process-cpu" ? baseline.cpu_seconds()
                                                         : *baseline.reported_seconds;
        EXPECT_DOUBLE_EQ(baseline.seconds, expected);
      }
    }
  }

  TempDir dir_;
  testing::GitFixture repo_;
  fs::path suite_ = dir_.path() / "identity-suite.json";
  fs::path simulated_suite_ = dir_.path() / "identity-sim-suite.json";
};

TEST_F(IdentityRatio, ProcessWallAgainstProcessWall) {
  const ResultsDocument d =
      measure_timed(adapter("identity", {{"source", "process"}, {"metric", "wall"}}, ""), {});
  expect_identity(d, "process-wall");
  EXPECT_EQ(d.settings.tracer_clock, "process-wall");
  EXPECT_EQ(d.settings.baseline_clock, "process-wall");
}

TEST_F(IdentityRatio, ProcessCpuAgainstProcessCpu) {
  const ResultsDocument d = measure_timed(
      adapter("identity", {{"source", "process"}, {"metric", "wall"}}, ""), {"--timing", "cpu"});
  expect_identity(d, "process-cpu");
  EXPECT_EQ(d.settings.tracer_clock, "process-cpu");
}

// A tracer that prints its own time is compared with the baseline's in-process seconds.
TEST_F(IdentityRatio, ReportedAgainstInProcess) {
  const json timing = {
      {"source", "reported"}, {"regex", "in-process seconds ([0-9.]+)"}, {"unit", "s"}};
  const ResultsDocument d = measure_timed(adapter("identity-reported", timing, "--print-time"), {});
  expect_identity(d, "in-process");
  EXPECT_EQ(d.settings.tracer_clock, "reported");
  // The tracer's seconds are the very number it printed: its in-process seconds.
  for (const SceneResult& s : d.scenes) {
    for (const Round& round : s.runs.rounds) {
      const RunRecord& tracer = round.runs.at("tracer");
      ASSERT_TRUE(tracer.reported_seconds) << s.entry.id;
      EXPECT_DOUBLE_EQ(tracer.seconds, *tracer.reported_seconds) << s.entry.id;
    }
  }
}

// The same yardstick under cachegrind: both sides' runs are simulated whole processes, the
// identity's being /bin/sh exec'ing the baseline, so its ratio is 1 to a tenth of a percent.
TEST_F(IdentityRatio, SimulatedCyclesAgainstSimulatedCyclesIsOne) {
  RAYGATE_SKIP_UNLESS_VALGRIND_RUNS_BASELINE();
  const ResultsDocument d =
      measure(adapter("identity", {{"source", "process"}, {"metric", "wall"}}, ""),
              {"--timing", "sim"}, simulated_suite_, "2");
  EXPECT_EQ(d.baseline.timing, "simulated-cycles");
  EXPECT_EQ(d.settings.tracer_clock, "simulated-cycles");
  ASSERT_EQ(d.scenes.size(), 2u);
  for (const SceneResult& s : d.scenes) {
    SCOPED_TRACE("scene " + s.entry.id);
    const RatioSummary* r = s.ratio(Role::tracer);
    ASSERT_NE(r, nullptr);
    EXPECT_NEAR(r->ratio, 1.0, kSimulatedTolerance);
  }
}

}  // namespace
}  // namespace raygate::test

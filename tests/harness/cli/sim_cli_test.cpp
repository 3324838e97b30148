// `--timing sim` end to end (docs/simulated-timing.md) on a throwaway repository of the fixture
// tracer (tracer_fixture.h) and on the identity tracer: every run under cachegrind, so an A/A
// compare is exactly 0, a tracer twice as slow is +100%, a +1% change is caught at a 0.5% limit
// after two rounds, the baseline is simulated once per scene, then read from the cache, and bisect
// finds a +10% commit among eight whose +0.3% commits are within the limit (the gate scenario's
// bisection, gate_scenario_cli_test.cpp, made exact: in timed mode its verdicts were the runner's).
// These tests need valgrind and fail (not skip) without it: CI installs it (ci/install-deps).
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "checkout/git_fixture.h"
#include "cli_support.h"
#include "results/results.h"
#include "tracer_fixture.h"
#include "valgrind_baseline.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

// One scene whose render (about 200 M instructions) dwarfs the tracer's start-up, so a change
// of the render shows at its full size in the whole process's cost; under valgrind each run
// takes a few seconds.
constexpr const char* kSimSuite = R"({
  "name": "sim-test",
  "description": "--timing sim's integration test: one small scene",
  "scenes": [{"id": "tetra", "scene": "tetra", "size": 4, "resolution": [64, 64]}]
})";

bool valgrind_installed() {
  ProcessSpec spec;
  spec.argv = {"valgrind", "--version"};
  return run_process(spec).succeeded();
}

class SimCli : public TracerRepoTest {
 protected:
  SimCli() : TracerRepoTest(kSimSuite) {}

  void SetUp() override {
    ASSERT_TRUE(valgrind_installed())
        << "valgrind is not installed: the --timing sim tests need it (Debian package valgrind; "
           "ci/install-deps installs it)";
  }

  // A `valgrind` first in PATH that logs each cachegrind command line, then runs the real one.
  fs::path counting_valgrind() const {
    const fs::path bin = dir_.path() / "counting-bin";
    fs::create_directories(bin);
    write_file_atomically(bin / "valgrind", "#!/bin/sh\necho \"$*\" >> \"" + calls_.string() +
                                                "\"\nPATH=\"" + std::getenv("PATH") +
                                                "\" exec valgrind \"$@\"\n");
    fs::permissions(bin / "valgrind", fs::perms::owner_all);
    return bin;
  }

  // The cachegrind runs logged so far whose command names `program`.
  int simulations_of(const std::string& program) const {
    if (!fs::exists(calls_)) return 0;
    int count = 0;
    const std::string log = read_file(calls_);
    for (std::size_t at = 0, end; at < log.size(); at = end + 1) {
      end = log.find('\n', at);
      const std::string line = log.substr(at, end - at);
      if (has(line, "--tool=cachegrind") && has(line, program)) ++count;
    }
    return count;
  }

  CliRun compare(const std::string& base, const std::string& head,
                 std::vector<std::string> extra = {}, const fs::path& path_first = {}) {
    std::vector<std::string> args{
        "compare",       "--base",       base,          "--head",        head,
        "--no-store",    "--out",        out_.string(), "--repo",        repo_.path().string(),
        "--adapter",     "make-nff",     "--suite",     suite_.string(), "--cache-dir",
        cache_.string(), "--golden-dir", "no-goldens",  "--timing",      "sim"};
    args.insert(args.end(), extra.begin(), extra.end());
    ProcessSpec spec = raygate_spec(args, dir_);
    if (!path_first.empty()) {
      spec.environment["PATH"] = path_first.string() + ":" + std::getenv("PATH");
    }
    const ProcessResult r = run_process(spec);
    return {r.outcome == ProcessOutcome::exited ? r.exit_code : -1, read_file(spec.stdout_path)};
  }

  const ChangeSummary& change() {
    document_ = read_results(out_);
    EXPECT_EQ(document_.scenes.size(), 1u);
    return document_.scenes.at(0).change.value();
  }

  fs::path out_ = dir_.path() / "c.json";
  fs::path calls_ = dir_.path() / "valgrind-calls.txt";
  ResultsDocument document_;
};

TEST_F(SimCli, AaCompareIsExactlyZeroAfterTwoRoundsAndTheBaselineIsThenCached) {
  RAYGATE_SKIP_UNLESS_VALGRIND_RUNS_BASELINE();
  const std::string sha = commit(sources_.fast, "tracer");
  const fs::path bin = counting_valgrind();
  const CliRun r = compare(sha, sha, {}, bin);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(has(r.out, "simulated cycles, counts repeat exactly")) << r.out;
  const ChangeSummary& c = change();
  EXPECT_TRUE(c.exact);
  EXPECT_EQ(c.change, 0.0);
  EXPECT_EQ(c.change_interval.lower, 0.0);
  EXPECT_EQ(c.change_interval.upper, 0.0);
  EXPECT_EQ(document_.scenes[0].change_verdict, ChangeVerdict::unchanged);
  ASSERT_EQ(document_.scenes[0].runs.rounds.size(), 2u);
  EXPECT_EQ(document_.settings.tracer_clock, "simulated-cycles");
  EXPECT_EQ(document_.baseline.timing, "simulated-cycles");
  EXPECT_EQ(document_.settings.max_slowdown, 0.01);  // sim mode's own default limit
  for (const Round& round : document_.scenes[0].runs.rounds) {
    for (const auto& [role, run] : round.runs) {
      ASSERT_TRUE(run.simulated) << role;  // the raw counters are in the document
      EXPECT_GT(run.simulated->ir, 0u);
      EXPECT_EQ(run.seconds, estimated_cycles(*run.simulated));
    }
  }
  // Two rounds of baseline, base and head, no warm-up.
  EXPECT_EQ(simulations_of("raygate-baseline"), 2);
  EXPECT_EQ(simulations_of("/tracer "), 4);

  // The next job knows the baseline's cost: only the tracer runs are simulated.
  const CliRun again = compare(sha, sha, {}, bin);
  EXPECT_EQ(again.exit_code, 0) << again.out;
  EXPECT_EQ(simulations_of("raygate-baseline"), 2) << read_file(calls_);
  EXPECT_EQ(simulations_of("/tracer "), 8);
  EXPECT_EQ(change().change, 0.0);
}

TEST_F(SimCli, TwiceSlowerHeadExitsOneAtPlusHundredPercent) {
  RAYGATE_SKIP_UNLESS_VALGRIND_RUNS_BASELINE();
  const std::string base = commit(sources_.fast, "tracer");
  // Parses and renders the scene twice (the second image checked, so it is not optimized
  // away): twice the work but the process's start-up and the image's writing, about 1%.
  const std::string head =
      commit(patched(sources_.fast, "  const std::vector<unsigned char> pixels = render(scene);\n",
                     "  const std::vector<unsigned char> pixels = render(scene);\n"
                     "  std::ifstream again(argv[1]);\n"
                     "  if (render(parse(again)) != pixels) return 3;\n"),
             "do everything twice");
  const CliRun r = compare(base, head);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  const ChangeSummary& c = change();
  EXPECT_TRUE(c.exact);
  EXPECT_NEAR(c.change, 1.0, 0.05);
  EXPECT_EQ(document_.scenes[0].change_verdict, ChangeVerdict::regressed);
}

TEST_F(SimCli, OnePercentSlowerHeadIsRegressedAtAHalfPercentLimit) {
  RAYGATE_SKIP_UNLESS_VALGRIND_RUNS_BASELINE();
  const std::string base = commit(sources_.fast, "tracer");
  const std::string head = commit(patched(sources_.fast, "constexpr int kRetraceEvery = 0;",
                                          "constexpr int kRetraceEvery = 100;"),
                                  "trace every 100th pixel once more");
  const fs::path policy = dir_.path() / "policy.json";
  write_file_atomically(policy, R"({"max_slowdown": 0.005})");
  const CliRun r = compare(base, head, {"--policy", policy.string()});
  EXPECT_EQ(r.exit_code, 1) << r.out;
  const ChangeSummary& c = change();
  EXPECT_TRUE(c.exact);
  EXPECT_GT(c.change, 0.005);
  EXPECT_LT(c.change, 0.015);
  EXPECT_EQ(document_.scenes[0].change_verdict, ChangeVerdict::regressed);
  EXPECT_EQ(document_.scenes[0].runs.rounds.size(), 2u);
}

TEST_F(SimCli, BisectFindsTheTenPercentCommitAmongEight) {
  RAYGATE_SKIP_UNLESS_VALGRIND_RUNS_BASELINE();
  const auto retracing = [this](int every) {
    return patched(sources_.fast, "constexpr int kRetraceEvery = 0;",
                   "constexpr int kRetraceEvery = " + std::to_string(every) + ";");
  };
  const std::string good = commit(sources_.fast, "tracer");
  repo_.write("README", "a tracer\n");
  commit(sources_.fast, "readme");
  const std::string small = retracing(300);  // +0.3%: within sim mode's 1% limit
  commit(small, "retrace every 300th pixel");
  repo_.write("README", "a ray tracer\n");
  commit(small, "readme: say what it traces");
  const std::string culprit = commit(retracing(9), "retrace every 9th pixel");  // +11%
  repo_.write("README", "a ray tracer for NFF scenes\n");
  commit(retracing(9), "readme: name the format");
  repo_.write("LICENSE", "public domain\n");
  commit(retracing(9), "license");
  repo_.write("README", "a small ray tracer for NFF scenes\n");
  const std::string bad = commit(retracing(9), "readme: small");
  const CliRun r =
      run_raygate({"bisect", "--good", good, "--bad", bad, "--scene", "tetra", "--repo",
                   repo_.path().string(), "--adapter", "make-nff", "--suite", suite_.string(),
                   "--cache-dir", cache_.string(), "--golden-dir", "no-goldens", "--timing", "sim"},
                  dir_);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(has(r.out, "bisecting 7 commits after")) << r.out;
  EXPECT_TRUE(has(r.out, "first bad commit: " + culprit)) << r.out;
}

TEST_F(SimCli, WithoutValgrindRaygateCannotMeasureAndSaysWhatToInstall) {
  const std::string sha = commit(sources_.fast, "tracer");
  const fs::path empty = dir_.path() / "no-valgrind-bin";
  fs::create_directories(empty);
  ProcessSpec spec;
  spec.argv = {RAYGATE_EXE,
               "compare",
               "--base",
               sha,
               "--head",
               sha,
               "--no-store",
               "--repo",
               repo_.path().string(),
               "--adapter",
               "make-nff",
               "--suite",
               suite_.string(),
               "--cache-dir",
               cache_.string(),
               "--timing",
               "sim"};
  spec.stdout_path = dir_.path() / "cli.log";
  spec.stderr_path = spec.stdout_path;
  spec.working_directory = dir_.path();
  spec.environment["PATH"] = empty.string();
  const ProcessResult r = run_process(spec);
  const std::string out = read_file(spec.stdout_path);
  EXPECT_EQ(r.exit_code, 3) << out;
  EXPECT_TRUE(has(out, "install Debian's valgrind package")) << out;
}

}  // namespace
}  // namespace raygate::test

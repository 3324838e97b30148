// Issue 27 end to end on a throwaway repository of the fixture tracer (tracer_fixture.h):
// - memory: a head that allocates +50 MiB per scene fails the memory gate on every scene
//   (exit 1) while an A/A compare passes memory on every scene; the peaks are the tracer's own;
// - explanation: a head whose shade() does more work is REGRESSED in sim mode, and shade() is
//   first among the functions whose cost grew, in the document and the console report; in timed
//   mode `--explain` profiles the regressed scene once each under callgrind and says so, with
//   self and inclusive instructions (main's inclusive change holds shade()'s);
//   bisect in sim mode ends with the culprit's explanation.
// The sim and --explain tests need valgrind and fail (not skip) without it (ci/install-deps).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "checkout/git_fixture.h"
#include "cli_support.h"
#include "gate/memory_gate.h"
#include "results/results.h"
#include "tracer_fixture.h"
#include "valgrind_baseline.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

// The fixture tracer with shade() kept out of line (so cachegrind names it) ...
std::string outlined(const std::string& source) {
  return patched(source, "V shade(const Scene& s, V o, V d) {",
                 "[[gnu::noinline]] V shade(const Scene& s, V o, V d) {");
}

// ... and a version whose shade() spins before shading: several times the render's work.
std::string slower_shade(const std::string& source) {
  return patched(outlined(source), "[[gnu::noinline]] V shade(const Scene& s, V o, V d) {",
                 "[[gnu::noinline]] V shade(const Scene& s, V o, V d) {\n"
                 "  for (volatile int spin = 0; spin < 3000; spin = spin + 1) {}");
}

// 50 MiB written page by page through a volatile pointer (so no compiler elides it): resident.
std::string ballast(const std::string& source) {
  return patched(source, "  const Scene scene = parse(in);\n",
                 "  const Scene scene = parse(in);\n"
                 "  volatile char* ballast = new char[50u << 20];\n"
                 "  for (unsigned i = 0; i < (50u << 20); i += 4096) ballast[i] = 1;\n");
}

constexpr const char* kSimSuite = R"({
  "name": "explain-sim",
  "description": "issue 27's sim test: one small scene",
  "scenes": [{"id": "tetra", "scene": "tetra", "size": 4, "resolution": [64, 64]}]
})";

class MemoryExplainCli : public TracerRepoTest {
 protected:
  explicit MemoryExplainCli(const char* suite = kTinySuite) : TracerRepoTest(suite) {}

  CliRun compare(const std::string& base, const std::string& head, std::vector<std::string> extra) {
    std::vector<std::string> args{
        "compare",       "--base",       base,          "--head",        head,
        "--no-store",    "--out",        out_.string(), "--repo",        repo_.path().string(),
        "--adapter",     "make-nff",     "--suite",     suite_.string(), "--cache-dir",
        cache_.string(), "--golden-dir", "no-goldens"};
    args.insert(args.end(), extra.begin(), extra.end());
    return run_raygate(args, dir_);
  }

  fs::path out_ = dir_.path() / "c.json";
};

TEST_F(MemoryExplainCli, FiftyMoreMebibytesFailTheMemoryGateOnEveryScene) {
  const std::string base = commit(sources_.fast, "tracer");
  const std::string head = commit(ballast(sources_.fast), "keep 50 MiB of ballast");
  const CliRun r = compare(
      base, head, {"--max-rounds", "3", "--report", "json:" + (dir_.path() / "r.json").string()});
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_TRUE(has(r.out, "memory (peak of the tracer's ")) << r.out;
  const ResultsDocument d = read_results(out_);
  ASSERT_EQ(d.scenes.size(), 2u);
  for (const SceneResult& scene : d.scenes) {
    EXPECT_TRUE(has(r.out, "more memory: head")) << r.out;
    for (const Round& round : scene.runs.rounds) {
      const RunRecord& b = round.runs.at("base");
      const RunRecord& h = round.runs.at("head");
      EXPECT_TRUE(b.max_rss_own && h.max_rss_own);
      EXPECT_LT(b.max_rss_kib, 30 * 1024) << "base's peak is the tracer's, not raygate's";
      EXPECT_NEAR(static_cast<double>(h.max_rss_kib - b.max_rss_kib), 50.0 * 1024, 2.0 * 1024);
    }
  }
  const nlohmann::json report = nlohmann::json::parse(read_file(dir_.path() / "r.json"));
  for (const nlohmann::json& scene : report.at("scenes")) {
    EXPECT_EQ(scene.at("memory").at("verdict"), "REGRESSED") << scene.dump();
  }
  // The summary says what failed, as for speed: "tetra memory +2900.0%", not "tetra failed".
  const CliRun markdown = run_raygate({"report", out_.string(), "--format", "markdown"}, dir_);
  EXPECT_TRUE(has(markdown.out, "tetra memory +")) << markdown.out;
  EXPECT_FALSE(has(markdown.out, "tetra failed")) << markdown.out;
}

TEST_F(MemoryExplainCli, AaComparePassesMemoryOnEveryScene) {
  const std::string sha = commit(sources_.fast, "tracer");
  const fs::path json = dir_.path() / "r.json";
  const CliRun r = compare(sha, sha, {"--max-rounds", "3", "--report", "json:" + json.string()});
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(has(r.out, "memory (peak of the tracer's ")) << r.out;
  const nlohmann::json report = nlohmann::json::parse(read_file(json));
  ASSERT_EQ(report.at("scenes").size(), 2u);
  for (const nlohmann::json& scene : report.at("scenes")) {
    EXPECT_EQ(scene.at("memory").at("verdict"), "UNCHANGED") << scene.dump();
    EXPECT_LT(scene.at("memory").at("base_peak_kib").get<double>(), 30 * 1024.0);
  }
  // `raygate gate` on the same document counts the memory verdicts.
  const CliRun gate = run_raygate({"gate", out_.string()}, dir_);
  EXPECT_EQ(gate.exit_code, 0) << gate.out;
  EXPECT_TRUE(has(gate.out, "memory: 2 UNCHANGED")) << gate.out;
}

// --explain in timed mode: the regressed scene profiled once each, and said to be.
TEST_F(MemoryExplainCli, ExplainProfilesOnlyTheRegressedScenesInTimedMode) {
  const std::string base = commit(outlined(sources_.fast), "tracer");
  const std::string head = commit(slower_shade(sources_.fast), "shade spins");
  const CliRun r = compare(base, head, {"--scene", "tetra", "--max-rounds", "30", "--explain"});
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_TRUE(has(r.out, "explained 1 regressed scene with valgrind")) << r.out;
  EXPECT_TRUE(has(r.out, "one profiled run each of base and head")) << r.out;
  const ResultsDocument d = read_results(out_);
  ASSERT_EQ(d.scenes.size(), 1u);
  ASSERT_TRUE(d.scenes[0].explanation.has_value()) << r.out;
  const Explanation& e = *d.scenes[0].explanation;
  EXPECT_EQ(e.source, ExplainSource::explain_runs);
  EXPECT_EQ(e.cost, ExplainCost::instructions);
  EXPECT_TRUE(e.inclusive);
  EXPECT_TRUE(e.profiler.find("callgrind") != std::string::npos) << e.profiler;
  ASSERT_FALSE(e.functions.empty());
  const FunctionChange& shade = e.functions[0];
  EXPECT_TRUE(shade.name.starts_with("shade(")) << shade.name;
  EXPECT_GT(share_of_change(e, shade), 0.9);
  EXPECT_GE(shade.head_inclusive_instructions, shade.head_instructions);
  EXPECT_TRUE(has(r.out, "inclusive base -> head")) << r.out;
  EXPECT_GT(e.profile_seconds, 0.0);
  EXPECT_GT(e.native_seconds, 0.0);
  EXPECT_TRUE(has(r.out, "profiling took")) << r.out;
}

class MemoryExplainSimCli : public MemoryExplainCli {
 protected:
  MemoryExplainSimCli() : MemoryExplainCli(kSimSuite) {}
};

TEST_F(MemoryExplainSimCli, ASlowerFunctionIsFirstInTheSimulatedExplanation) {
  RAYGATE_SKIP_UNLESS_VALGRIND_RUNS_BASELINE();
  const std::string base = commit(outlined(sources_.fast), "tracer");
  const std::string head = commit(slower_shade(sources_.fast), "shade spins");
  const CliRun r = compare(
      base, head, {"--timing", "sim", "--report", "markdown:" + (dir_.path() / "r.md").string()});
  EXPECT_EQ(r.exit_code, 1) << r.out;
  const ResultsDocument d = read_results(out_);
  ASSERT_EQ(d.scenes.size(), 1u);
  EXPECT_EQ(d.scenes[0].change_verdict, ChangeVerdict::regressed);
  ASSERT_TRUE(d.scenes[0].explanation.has_value()) << r.out;
  const Explanation& e = *d.scenes[0].explanation;
  EXPECT_EQ(e.source, ExplainSource::simulated_runs);
  ASSERT_FALSE(e.functions.empty());
  EXPECT_TRUE(e.functions[0].name.starts_with("shade(")) << e.functions[0].name;
  EXPECT_GT(share_of_change(e, e.functions[0]), 0.9);
  EXPECT_TRUE(has(r.out, "tetra: where the time went (valgrind")) << r.out;
  EXPECT_TRUE(has(read_file(dir_.path() / "r.md"), "shade(")) << read_file(dir_.path() / "r.md");
}

TEST_F(MemoryExplainSimCli, BisectEndsWithTheCulpritsExplanation) {
  RAYGATE_SKIP_UNLESS_VALGRIND_RUNS_BASELINE();
  const std::string good = commit(outlined(sources_.fast), "tracer");
  const std::string bad = commit(slower_shade(sources_.fast), "shade spins");
  const CliRun r =
      run_raygate({"bisect", "--good", good, "--bad", bad, "--scene", "tetra", "--repo",
                   repo_.path().string(), "--adapter", "make-nff", "--suite", suite_.string(),
                   "--cache-dir", cache_.string(), "--golden-dir", "no-goldens", "--timing", "sim"},
                  dir_);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  const std::size_t answer = r.out.find("first bad commit: " + bad);
  ASSERT_NE(answer, std::string::npos) << r.out;
  const std::size_t why =
      r.out.find("the culprit against the good end, where the time went", answer);
  ASSERT_NE(why, std::string::npos) << r.out;
  EXPECT_NE(r.out.find("shade(", why), std::string::npos) << r.out;
}

TEST_F(MemoryExplainSimCli, AnUnchangedSceneIsNotExplained) {
  RAYGATE_SKIP_UNLESS_VALGRIND_RUNS_BASELINE();
  const std::string sha = commit(outlined(sources_.fast), "tracer");
  const CliRun r = compare(sha, sha, {"--timing", "sim"});
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_FALSE(read_results(out_).scenes.at(0).explanation.has_value());
  EXPECT_FALSE(has(r.out, "explained")) << r.out;
  // The peak metered under cachegrind is valgrind's: not judged or printed as the tracer's.
  EXPECT_FALSE(scene_memory(read_results(out_).scenes.at(0)).has_value());
}

}  // namespace
}  // namespace raygate::test

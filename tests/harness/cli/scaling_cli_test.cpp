// The complexity gate end to end (docs/scaling.md): a throwaway repository of the example tracer
// (examples/nff-tracer, BVH) and a commit of it that tests every shape for primary rays
// (examples/nff-tracer/linear-primary.patch). `raygate compare` on a small scaling suite must
// fail on the growth exponent and say by how much; `raygate scaling` judges the stored document
// again, and a policy that allows the change passes it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "checkout/git_fixture.h"
#include "cli_support.h"
#include "core/fs.h"
#include "core/process.h"
#include "scaling/scaling_analysis.h"
#include "results/results.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSource(RAYGATE_SOURCE_DIR);

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}
const fs::path kExample = kSource / "examples" / "nff-tracer";

// Small enough for a test (20 s of CPU; on a 2-core VM shared at load 17, 3 minutes of wall
// time) and still three decades of primitives: balls grows ninefold per size. 48x48 pixels
// make the primary rays' linear cost dominate head's time at the two largest sizes.
constexpr const char* kSuite = R"({
  "name": "scaling-test",
  "scenes": [
    {"id": "balls-s1", "scene": "balls", "size": 1, "resolution": [48, 48]},
    {"id": "balls-s2", "scene": "balls", "size": 2, "resolution": [48, 48]},
    {"id": "balls-s3", "scene": "balls", "size": 3, "resolution": [48, 48]},
    {"id": "balls-s4", "scene": "balls", "size": 4, "resolution": [48, 48]}
  ]
})";

// One g++ call instead of CMake: the same sources and flags class, a fraction of the set-up.
constexpr const char* kAdapter = R"({
  "name": "nff-tracer-test",
  "scene_format": "nff",
  "build": [["g++", "-O2", "-std=c++17", "-o", "{build}/tracer",
             "{src}/src/main.cpp", "{src}/src/nff_reader.cpp", "{src}/src/shapes.cpp",
             "{src}/src/bvh.cpp", "{src}/src/image.cpp"]],
  "run": ["{build}/tracer", "{scene}", "-o", "{image}"],
  "image": "{image}",
  "timing": {"source": "process", "metric": "cpu"},
  "threads": 1
})";

class ScalingCli : public ::testing::Test {
 protected:
  ScalingCli() : repo_(dir_.path() / "nff-tracer") {
    write_file_atomically(dir_.path() / "suite.json", kSuite);
    write_file_atomically(dir_.path() / "adapter.json", kAdapter);
    fs::create_directories(dir_.path() / "no-goldens");
    for (const auto& entry : fs::recursive_directory_iterator(kExample)) {
      if (!entry.is_regular_file()) continue;
      repo_.write(fs::relative(entry.path(), kExample).string(), read_file(entry.path()));
    }
    base_ = repo_.commit("nff-tracer with its BVH");
    apply_patch("linear-primary.patch");
    head_ = repo_.commit("primary rays: test every shape");
  }

  void apply_patch(const std::string& name) {
    ProcessSpec spec;
    spec.argv = {"git", "apply", (kExample / name).string()};
    spec.working_directory = repo_.path();
    spec.stdout_path = dir_.path() / "git-apply.log";
    spec.stderr_path = spec.stdout_path;
    const ProcessResult r = run_process(spec);
    ASSERT_EQ(r.exit_code, 0) << read_file(spec.stdout_path);
  }

  CliRun compare(const std::string& base, const std::string& head) {
    return run_raygate({"compare",      "--base",
                        base,           "--head",
                        head,           "--no-store",
                        "--out",        (dir_.path() / "c.json").string(),
                        "--repo",       repo_.path().string(),
                        "--adapter",    "adapter.json",
                        "--suite",      "suite.json",
                        "--cache-dir",  ".raygate",
                        "--golden-dir", "no-goldens",
                        "--warmup",     "0",
                        "--min-rounds", "3",
                        "--max-rounds", "3",
                        "--timing",     "cpu"},
                       dir_);
  }

  TempDir dir_;
  testing::GitFixture repo_;
  std::string base_, head_;
};

TEST_F(ScalingCli, LinearPrimaryRaysFailTheGateOnTheExponentAndSayByHowMuch) {
  const CliRun r = compare(base_, head_);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_TRUE(has(r.out, "scaling balls: 4 sizes, 11..7382 primitives")) << r.out;
  EXPECT_TRUE(has(r.out, "  exponent head - base +")) << r.out;
  EXPECT_TRUE(has(r.out, "raygate: growth regressed in 1 scene family")) << r.out;
  EXPECT_TRUE(has(r.out, "REGRESSED")) << r.out;
  EXPECT_TRUE(has(r.out, "head is projected +")) << r.out;

  const ResultsDocument d = read_results(dir_.path() / "c.json");
  ASSERT_TRUE(d.scaling.has_value());
  const ScalingAnalysis& a = *d.scaling;
  ASSERT_EQ(a.families.size(), 1u);
  const FamilyScaling& balls = a.families[0];
  ASSERT_TRUE(balls.change);
  EXPECT_EQ(balls.change->verdict, ChangeVerdict::regressed);
  EXPECT_GT(balls.change->judged().exponent, 0.1);
  // The BVH tracer grows far more slowly than the baseline, which tests every primitive.
  EXPECT_LT(balls.roles.at(Role::base).time.exponent, balls.baseline.exponent);
  EXPECT_GT(balls.roles.at(Role::head).time.exponent, balls.roles.at(Role::base).time.exponent);

  // The same document judged again: a policy that allows the exponent to rise passes it
  // (the per-scene speed verdicts are not `raygate scaling`'s to judge).
  write_file_atomically(dir_.path() / "loose.json", R"({"max_exponent_increase": 5})");
  const CliRun loose = run_raygate({"scaling", "c.json", "--policy", "loose.json"}, dir_);
  EXPECT_EQ(loose.exit_code, 0) << loose.out;
  const CliRun again = run_raygate({"scaling", "c.json", "--no-write"}, dir_);
  EXPECT_EQ(again.exit_code, 1) << again.out;
  EXPECT_TRUE(has(again.out, "fail       scaling:balls balls growth: exponent head - base +"))
      << again.out;

  // The eleventh sweep: a report over the document it reads replaced it; rewriting the fits
  // dropped a newer raygate's keys.
  const std::string kept = read_file(dir_.path() / "c.json");
  const CliRun over = run_raygate({"scaling", "c.json", "--report", "html:c.json"}, dir_);
  EXPECT_EQ(over.exit_code, 2) << over.out;
  EXPECT_EQ(read_file(dir_.path() / "c.json"), kept);
  nlohmann::json newer = nlohmann::json::parse(kept);
  newer["zz_future"] = 1;
  newer["scenes"][0]["zz_scene_future"] = "x";
  write_file_atomically(dir_.path() / "c.json", newer.dump(1) + "\n");
  EXPECT_EQ(run_raygate({"scaling", "c.json"}, dir_).exit_code, 1);
  const nlohmann::json rewritten = nlohmann::json::parse(read_file(dir_.path() / "c.json"));
  EXPECT_EQ(rewritten["zz_future"], 1);
  EXPECT_EQ(rewritten["scenes"][0]["zz_scene_future"], "x");
  EXPECT_TRUE(rewritten.contains("scaling"));
}

TEST_F(ScalingCli, ADocumentWithoutSizesToFitIsAUsageError) {
  write_file_atomically(dir_.path() / "suite.json", R"({"name": "one", "scenes": [
    {"id": "tetra", "scene": "tetra", "size": 3, "resolution": [16, 16]}]})");
  const CliRun run = run_raygate({"run",          "--rev",
                                  base_,          "--no-store",
                                  "--out",        "r.json",
                                  "--repo",       repo_.path().string(),
                                  "--adapter",    "adapter.json",
                                  "--suite",      "suite.json",
                                  "--cache-dir",  ".raygate",
                                  "--golden-dir", "no-goldens",
                                  "--warmup",     "0",
                                  "--max-rounds", "1"},
                                 dir_);
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_FALSE(has(run.out, "scaling ")) << run.out;
  const CliRun r = run_raygate({"scaling", "r.json"}, dir_);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_TRUE(has(r.out, "no scene family was measured at 3 sizes or more")) << r.out;
}

}  // namespace
}  // namespace raygate::test

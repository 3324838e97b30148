// The Monte Carlo image verdict end to end on the example path tracer (examples/path-tracer):
// a throwaway repository of it and one branch per change in examples/path-tracer/changes/.
// `raygate compare` of each against the original, through an adapter with "images":
// "monte-carlo" and {seed}, must pass the changes that alter only the noise (another seed, more
// samples, a stratified sampler) and fail the biased ones (a light 3% dimmer, energy lost at
// grazing angles, polygons casting no shadows), saying where and by how much. Then goldens:
// `golden bless --from-run` stores a run's mean and variance, and `golden verify --from-run`
// passes a run with other seeds and fails a run of the dimmer light.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "checkout/git_fixture.h"
#include "cli_support.h"
#include "compare/golden.h"
#include "core/fs.h"
#include "core/process.h"
#include "results/results.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSource(RAYGATE_SOURCE_DIR);
const fs::path kExample = kSource / "examples" / "path-tracer";

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Tiny on purpose: 48x48 pixels at the tracer's 16 samples per pixel render in a few
// hundredths of a second, so 9 runs a side cost less than the two builds of a compare.
constexpr const char* kSuite = R"({
  "name": "mc-test",
  "scenes": [
    {"id": "balls", "scene": "balls", "size": 1, "resolution": [48, 48]},
    {"id": "gears", "scene": "gears", "size": 1, "resolution": [48, 48]}
  ]
})";

// One g++ call on one translation unit that includes every source, instead of CMake (as in
// scaling_cli_test): the same code, and the headers parsed once. The builds are most of this
// test's time: 4.5 s a commit on the 2-core VM, where the seven files one by one took 8.8 s.
// -O1 builds faster than -O2 and the renders are tiny.
constexpr const char* kAdapter = R"({
  "name": "path-tracer-test",
  "scene_format": "nff",
  "build": [["sh", "-c", "for f in {src}/src/*.cpp; do echo \"#include \\\"$f\\\"\"; done > {build}/all.cpp"],
            ["g++", "-O1", "-std=c++17", "-o", "{build}/tracer", "{build}/all.cpp"]],
  "run": ["{build}/tracer", "{scene}", "-o", "{workdir}/image.pfm", "--seed", "{seed}"],
  "image": "{workdir}/image.pfm",
  "images": "monte-carlo",
  "timing": {"source": "process", "metric": "cpu"},
  "threads": 1
})";

// Speed is not what this test is about ("more samples" is slower on purpose).
constexpr const char* kPolicy = R"({"max_slowdown": 10})";

// One raygate cache for both tests: the fixture's commits are the same bytes at the same times,
// so their shas repeat and each commit is built once (the builds are most of this test's time).
const TempDir& shared_cache() {
  static const TempDir cache("raygate-mc-cache");
  return cache;
}

struct Change {
  const char* patch;
  bool biased;
};

constexpr Change kChanges[] = {
    {"another-seed", false}, {"more-samples", false},       {"stratified-sampler", false},
    {"dimmer-light", true},  {"grazing-energy-loss", true}, {"polygons-cast-no-shadows", true},
};

class PathTracerImages : public ::testing::Test {
 protected:
  PathTracerImages() : repo_(dir_.path() / "path-tracer") {
    write_file_atomically(dir_.path() / "suite.json", kSuite);
    write_file_atomically(dir_.path() / "adapter.json", kAdapter);
    write_file_atomically(dir_.path() / "policy.json", kPolicy);
    fs::create_directories(dir_.path() / "no-goldens");
    for (const auto& entry : fs::recursive_directory_iterator(kExample)) {
      if (!entry.is_regular_file()) continue;
      repo_.write(fs::relative(entry.path(), kExample).string(), read_file(entry.path()));
    }
    base_ = repo_.commit("path tracer");
  }

  // A branch off the original with the patch applied and committed.
  void commit_change(const std::string& patch) {
    repo_.switch_to("main");
    repo_.branch(patch);
    repo_.switch_to(patch);
    ProcessSpec spec;
    spec.argv = {"git", "apply", (kExample / "changes" / (patch + ".patch")).string()};
    spec.working_directory = repo_.path();
    spec.stdout_path = dir_.path() / "git-apply.log";
    spec.stderr_path = spec.stdout_path;
    ASSERT_EQ(run_process(spec).exit_code, 0) << read_file(spec.stdout_path);
    repo_.commit(patch);
  }

  std::vector<std::string> measure_args() const {
    return {"--no-store",
            "--repo",
            repo_.path().string(),
            "--adapter",
            "adapter.json",
            "--suite",
            "suite.json",
            "--cache-dir",
            shared_cache().path().string(),
            "--policy",
            "policy.json",
            "--warmup",
            "1",
            "--min-rounds",
            "8",
            "--max-rounds",
            "8",
            "--timing",
            "cpu"};
  }

  CliRun compare(const std::string& head, const std::string& out) {
    std::vector<std::string> args{"compare",  "--base", base_,          "--head",    head,
                                  "--output", out,      "--golden-dir", "no-goldens"};
    for (const std::string& a : measure_args()) args.push_back(a);
    return run_raygate(args, dir_);
  }

  CliRun run(const std::string& rev, const std::string& out, const std::string& goldens) {
    std::vector<std::string> args{"run", "--rev", rev, "--output", out, "--golden-dir", goldens};
    for (const std::string& a : measure_args()) args.push_back(a);
    return run_raygate(args, dir_);
  }

  TempDir dir_;
  testing::GitFixture repo_;
  std::string base_;
};

// The head-vs-base image check of every scene in a compare document.
std::vector<ImageCheck> head_checks(const fs::path& document) {
  std::vector<ImageCheck> checks;
  for (const SceneResult& scene : read_results(document).scenes) {
    for (const ImageCheck& check : scene.images) {
      if (check.role == Role::head && check.reference == ImageReference::base)
        checks.push_back(check);
    }
  }
  return checks;
}

TEST_F(PathTracerImages, NoiseOnlyChangesPassAndBiasedOnesFailSayingWhere) {
  for (const Change& change : kChanges) {
    SCOPED_TRACE(change.patch);
    commit_change(change.patch);
    const std::string out = std::string(change.patch) + ".json";
    const CliRun r = compare(change.patch, out);
    EXPECT_EQ(r.exit_code, change.biased ? 1 : 0) << r.out;
    const std::vector<ImageCheck> checks = head_checks(dir_.path() / out);
    ASSERT_EQ(checks.size(), 2u) << r.out;
    bool any_failed = false;
    for (const ImageCheck& check : checks) {
      const std::string detail = check_detail(check);
      std::printf("%-26s %s\n", change.patch, detail.c_str());
      EXPECT_FALSE(check.metrics.has_value());  // the per-pixel rule was not used
      ASSERT_TRUE(check.noisy.has_value());     // the Monte Carlo comparison, typed
      if (!change.biased) {
        EXPECT_EQ(check.verdict, ImageVerdict::pass) << detail;
        EXPECT_TRUE(has(detail, "pass (within the ±1% image tolerance)")) << detail;
        // The runs of the last look, 8 rounds (pipeline/image_stop.h); not the warm-up.
        EXPECT_TRUE(has(detail, "8 vs 8 runs")) << detail;
      }
      if (check.verdict == ImageVerdict::fail) {
        any_failed = true;
        EXPECT_TRUE(has(detail, "fail (")) << detail;
        EXPECT_GT(check.noisy->biased_count, 0u) << detail;
        ASSERT_EQ(check.evidence.size(), 3u);
        EXPECT_TRUE(fs::exists(check.evidence[2])) << check.evidence[2];  // the tile map
      }
    }
    EXPECT_EQ(any_failed, change.biased) << r.out;
    if (change.biased) {
      EXPECT_TRUE(has(r.out, "image head-vs-base fail (")) << r.out;
    }
  }
}

TEST_F(PathTracerImages, GoldensStoreTheRunsStatisticsAndJudgeWithinNoise) {
  const CliRun first = run(base_, "first.json", "no-goldens");
  ASSERT_EQ(first.exit_code, 0) << first.out;
  const CliRun bless =
      run_raygate({"golden", "bless", "--from-run", "first.json", "--golden-dir", "goldens"}, dir_);
  ASSERT_EQ(bless.exit_code, 0) << bless.out;
  EXPECT_TRUE(has(bless.out, "mean and variance of 9 runs"))
      << bless.out;  // a warm-up and 8 rounds
  const GoldenManifest manifest = load_golden_manifest(dir_.path() / "goldens");
  ASSERT_EQ(manifest.entries.size(), 2u);
  ASSERT_EQ(manifest.noise.count("balls"), 1u);
  EXPECT_EQ(manifest.noise.at("balls").runs, 9);
  EXPECT_TRUE(fs::exists(dir_.path() / "goldens" / "balls.variance.exr"));

  // Other seeds (another commit's stream salt): the same picture within noise.
  commit_change("another-seed");
  const CliRun again = run("another-seed", "again.json", "goldens");
  EXPECT_EQ(again.exit_code, 0) << again.out;
  const CliRun same = run_raygate(
      {"golden", "verify", "--from-run", "again.json", "--golden-dir", "goldens"}, dir_);
  EXPECT_EQ(same.exit_code, 0) << same.out;
  EXPECT_TRUE(has(same.out, "2 scenes: 2 same, 0 different")) << same.out;

  commit_change("dimmer-light");
  const CliRun dim = run("dimmer-light", "dim.json", "goldens");
  EXPECT_EQ(dim.exit_code, 1) << dim.out;  // the run itself fails on its goldens
  const CliRun different =
      run_raygate({"golden", "verify", "--from-run", "dim.json", "--golden-dir", "goldens"}, dir_);
  EXPECT_EQ(different.exit_code, 1) << different.out;
  EXPECT_TRUE(has(different.out, "DIFFERENT")) << different.out;
  EXPECT_TRUE(has(different.out, "fail (")) << different.out;
}

}  // namespace
}  // namespace raygate::test

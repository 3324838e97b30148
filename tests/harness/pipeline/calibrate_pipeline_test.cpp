// `raygate calibrate` as a library call (pipeline/calibrate.h) on the fixture's tracer, built for
// real, whose renders the fake executor times as 0.1 s plus 1e-4 s a pixel of the scene it is
// given; and the written suite measured by compare, whose estimate is said before its rounds
// go on (pipeline/measurement_estimate.h).
#include "pipeline/calibrate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <regex>
#include <sstream>

#include "pipeline/compare_measurement.h"
#include "pipeline_fixture.h"

namespace raygate::testing {
namespace {

namespace fs = std::filesystem;

constexpr double kFixedSeconds = 0.1;
constexpr double kSecondsPerPixel = 1e-4;

// The pixels of the view in the NFF file a tracer run is given.
double scene_pixels(const fs::path& nff) {
  std::istringstream text(read_file(nff));
  std::string word;
  while (text >> word) {
    if (word == "resolution") {
      double width = 0;
      double height = 0;
      text >> width >> height;
      return width * height;
    }
  }
  return 0.0;
}

class CalibratePipelineTest : public PipelineTest {
 protected:
  CalibratePipelineTest() {
    // The fixture's scenes at 64x64: calibrate chooses smaller pictures, never larger.
    const fs::path suite = dir_.path() / "calibrate-test.json";
    write_file_atomically(suite, R"({"name": "calibrate-test", "scenes": [
      {"id": "tetra", "scene": "tetra", "size": 1, "resolution": [64, 64]},
      {"id": "balls", "scene": "balls", "size": 1, "resolution": [64, 64]}]})");
    context_.suite = load_suite(suite.string(), context_.tools.data_root);
    context_.scenes = select_scenes(context_.suite, {});
    executor_.time_by([](const ProcessSpec& spec) -> std::optional<double> {
      if (fs::path(spec.argv.at(0)).filename() != "tracer") return 1.0;  // the baseline
      return kFixedSeconds + kSecondsPerPixel * scene_pixels(spec.argv.at(1));
    });
  }

  Calibration calibrate(const std::string& rev, double target_seconds, const fs::path& out) {
    const Repository repository = Repository::open(repo_.path().string(), context_.cache_dir);
    CalibrateRequest request{
        context_, baseline_, repository.location(), repository.checkout(rev), target_seconds, 1, 16,
        "",       out};
    return calibrate_suite(request, io_);
  }
};

TEST_F(CalibratePipelineTest, WritesASuiteWhoseRendersTakeTheTarget) {
  const std::string sha = commit_tracer("1.0", "a tracer");
  const fs::path out = dir_.path() / "adapters" / "fake.suite.json";
  const Calibration calibration = calibrate(sha, 0.2, out);
  // 0.2 s = 0.1 s fixed + 1,000 pixels: 32x32 of the square 64x64 suite.
  ASSERT_EQ(calibration.scenes.size(), 2u);
  for (const SceneCalibration& scene : calibration.scenes) {
    EXPECT_EQ(scene.larger.width, 64);
    EXPECT_EQ(scene.smaller.width, 32);
    EXPECT_NEAR(scene.larger.seconds, 0.1 + 4096e-4, 1e-9);
    EXPECT_NEAR(scene.model.fixed_seconds, kFixedSeconds, 1e-9);
    EXPECT_EQ(scene.chosen.width, 32);
    EXPECT_EQ(scene.chosen.height, 32);
    EXPECT_TRUE(scene.chosen.reached);
  }
  // Read back as any suite is, ids, scenes and sizes as they were.
  const Suite written = load_suite(out.string(), context_.tools.data_root);
  EXPECT_EQ(written.name, "calibrate-test-fake-cost-tracer");
  ASSERT_EQ(written.scenes.size(), 2u);
  EXPECT_EQ(written.scenes[0].id, "tetra");
  EXPECT_EQ(written.scenes[0].size, 1);
  EXPECT_EQ(written.scenes[1].width, 32);
  EXPECT_NE(written.description.find("fake-cost-tracer"), std::string::npos);
  // What it did, a line per scene.
  const std::vector<std::string> lines = progress_.lines_with("-> 32x32");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("64x64 0.510 s, 32x32 0.202 s -> 32x32, predicted 0.202 s"),
            std::string::npos)
      << lines[0];
}

TEST_F(CalibratePipelineTest, ACompareOnTheCalibratedSuiteSaysItsEstimateFirst) {
  const std::string base = commit_tracer("1.0", "base");
  const std::string head = commit_tracer("1.0", "head: the same");
  const fs::path out = dir_.path() / "calibrated.json";
  calibrate(head, 0.3, out);  // 2,000 pixels: 45x45
  context_.suite = load_suite(out.string(), context_.tools.data_root);
  context_.scenes = select_scenes(context_.suite, {});
  context_.stopping = change_stopping_policy();
  context_.schedule.normalizer_rounds = kChangeBaselineRounds;
  const Repository repository = Repository::open(repo_.path().string(), context_.cache_dir);
  progress_.lines.clear();
  const double started = clock_.now_seconds();
  // The estimate is of the verdicts; ratio rounds come after them, from what the budget has
  // left, and are left out here (exact times would give every scene three).
  const MeasuredDocument measured = measure_compare({context_,
                                                     baseline_,
                                                     repository.location(),
                                                     repository.checkout(base),
                                                     repository.checkout(head),
                                                     {},
                                                     false},
                                                    io_);
  const double took = clock_.now_seconds() - started;
  for (const SceneResult& scene : measured.document.scenes) {
    EXPECT_EQ(scene.entry.width, 45);
    EXPECT_EQ(scene.change_verdict, ChangeVerdict::unchanged) << scene.entry.id;
  }
  const std::vector<std::string> first = progress_.lines_with("tetra's first round");
  ASSERT_EQ(first.size(), 1u);
  // Said after the first round of the first scene, before the scene's line.
  EXPECT_LT(std::find(progress_.lines.begin(), progress_.lines.end(), first[0]),
            std::find(progress_.lines.begin(), progress_.lines.end(),
                      progress_.lines_with("[1/2]").at(0)));
  // Once tetra is decided, its rounds say how long the compare takes: with exact times, all.
  const std::vector<std::string> after = progress_.lines_with("estimate from tetra (decided");
  ASSERT_EQ(after.size(), 1u);
  std::smatch total;
  ASSERT_TRUE(std::regex_search(after[0], total, std::regex("= ([0-9.]+) (s|min)")));
  const double estimated = std::stod(total[1]) * (total[2] == "min" ? 60.0 : 1.0);
  EXPECT_NEAR(estimated, took, 0.05 * took) << after[0];
}

TEST_F(CalibratePipelineTest, NeverChoosesAPictureLargerThanTheSuites) {
  // 0.1 s fixed + 0.41 s at 64x64: 10 s would need about 315x315, which the baseline renders too.
  const Calibration calibration =
      calibrate(commit_tracer("1.0", "a tracer"), 10.0, dir_.path() / "s.json");
  for (const SceneCalibration& scene : calibration.scenes) {
    EXPECT_EQ(scene.chosen.width, 64);
    EXPECT_FALSE(scene.chosen.reached);
  }
  EXPECT_EQ(progress_.lines_with("NOT REACHED: under 10 s at the suite's own resolution").size(),
            2u);
}

TEST_F(CalibratePipelineTest, RefusesBadRequestsBeforeBuilding) {
  const std::string sha = commit_tracer("1.0", "a tracer");
  EXPECT_THROW(calibrate(sha, 0.0, dir_.path() / "s.json"), UsageError);
  EXPECT_THROW(calibrate(sha, 1.0, dir_.path()), UsageError);                // a directory
  EXPECT_THROW(calibrate(sha, 1.0, dir_.path() / "suite.txt"), UsageError);  // not .json
  const std::string suite_before = read_file(context_.suite.path);
  EXPECT_THROW(calibrate(sha, 1.0, context_.suite.path), UsageError);  // the suite it reads
  EXPECT_EQ(read_file(context_.suite.path), suite_before);
  EXPECT_TRUE(executor_.calls().empty());
}

TEST_F(CalibratePipelineTest, ATracerThatFailsIsAnInfrastructureErrorNamingTheScene) {
  EXPECT_THROW(calibrate(commit_tracer("", "does not build"), 1.0, dir_.path() / "s.json"),
               InfraError);
  const std::string sha = commit_tracer("1.0", "a tracer");
  calibrate(sha, 1.0, dir_.path() / "first.json");
  const std::string program = executor_.calls().back().role;
  // Its next run (tetra at 32x32) exits 1.
  executor_.script(program, static_cast<int>(executor_.calls().size()) + 1, exited_with(1, 0.1));
  const fs::path out = dir_.path() / "second.json";
  try {
    calibrate(sha, 1.0, out);
    FAIL() << "no error";
  } catch (const InfraError& e) {
    EXPECT_NE(std::string(e.what()).find("tetra at 32x32: the tracer failed"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(out));  // nothing half-written
}

}  // namespace
}  // namespace raygate::testing

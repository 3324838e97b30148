// pipeline/golden_images: blessing a foreign tracer's images from a run, in process. What the run
// made is copied with its provenance; a document naming a scene "../x", an image that is not an
// image file, or an image that is gone blesses nothing at all.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "compare/golden.h"
#include "core/error.h"
#include "core/fs.h"
#include "pipeline/golden_images.h"
#include "results_fixture.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

// Keeps the lines the stage says.
class LineLog final : public ProgressSink {
 public:
  void update(const ProgressState&) override {}
  void line(const std::string& text) override { lines.push_back(text); }
  void status(const std::string& text) override { lines.push_back(text); }
  std::vector<std::string> lines;
};

class BlessFromRunTest : public ::testing::Test {
 protected:
  BlessFromRunTest() {
    DocumentSpec spec;
    spec.sha = fake_sha(1);
    spec.adapter = "make-nff";
    spec.scenes = {{"balls"}, {"gears"}};
    document_ = make_document(spec);
    for (SceneResult& scene : document_.scenes) {
      const fs::path image = dir_.path() / "run" / (scene.entry.id + ".ppm");
      fs::create_directories(image.parent_path());
      write_file_atomically(image, "P3\n1 1\n255\n10 20 30\n");  // one real pixel
      scene.runs.rounds.at(0).runs.at("tracer").image = image;
    }
    request_.results = dir_.path() / "run.json";
    request_.golden_dir = dir_.path() / "golden";
  }

  void bless() {
    write_results(document_, request_.results);
    bless_goldens_from_run(request_, log_);
  }

  RunRecord& tracer_run(std::size_t scene) {
    return document_.scenes.at(scene).runs.rounds.at(0).runs.at("tracer");
  }

  TempDir dir_;
  ResultsDocument document_;
  BlessFromRun request_;
  LineLog log_;
};

TEST_F(BlessFromRunTest, CopiesEachImageWithTheRunsProvenance) {
  bless();
  EXPECT_EQ(read_file(request_.golden_dir / "balls.ppm"), read_file(tracer_run(0).image));
  const GoldenManifest manifest = load_golden_manifest(request_.golden_dir);
  ASSERT_TRUE(manifest.tracer);
  EXPECT_EQ(manifest.tracer->adapter, "make-nff");
  EXPECT_EQ(manifest.suite, "ci");
  ASSERT_NE(manifest.find("gears"), nullptr);
  EXPECT_EQ(manifest.find("gears")->width, 1);
  ASSERT_EQ(log_.lines.size(), 2u);
  EXPECT_TRUE(log_.lines[0].starts_with("blessed   balls")) << log_.lines[0];
}

TEST_F(BlessFromRunTest, AHostileDocumentBlessesNothing) {
  document_.scenes.at(1).entry.id = "../escape";
  EXPECT_THROW(bless(), UsageError);
  EXPECT_FALSE(fs::exists(request_.golden_dir));

  document_.scenes.at(1).entry.id = "gears";
  tracer_run(1).image = dir_.path() / "run" / "manifest.json";
  write_file_atomically(tracer_run(1).image, "{}");
  EXPECT_THROW(bless(), UsageError);
  EXPECT_FALSE(fs::exists(request_.golden_dir));

  tracer_run(1).image = dir_.path() / "run" / "gone.ppm";
  try {
    bless();
    ADD_FAILURE() << "a missing image was blessed";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("is gone"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(request_.golden_dir));
  EXPECT_TRUE(log_.lines.empty());
}

TEST_F(BlessFromRunTest, AnotherAdaptersGoldensAreNotOverwritten) {
  bless();
  document_.revisions.at(0).adapter_name = "cmake-nff";
  try {
    bless();
    ADD_FAILURE() << "blessed over make-nff's goldens";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("holds goldens of adapter 'make-nff'"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace raygate::test

// A foreign tracer end to end: `raygate run --adapter povray` renders converted ci scenes with
// Debian's POV-Ray, measures its ratio against the baseline and checks its images against the
// shipped golden/povray/ (skipped when povray is not on PATH). And `raygate golden bless
// --from-run`, which turns a run's images into a tracer's goldens, on a hand-made document.
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "cli_support.h"
#include "compare/golden.h"
#include "core/sha256.h"
#include "results/results.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path != nullptr ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
  }
  return false;
}

const SceneResult* scene_of(const ResultsDocument& doc, const std::string& id) {
  for (const SceneResult& s : doc.scenes) {
    if (s.entry.id == id) return &s;
  }
  return nullptr;
}

// About 15 s: two ci scenes, one warm-up and three rounds each, POV-Ray's 0.6 s of console
// polling included.
TEST(PovrayCli, RunMeasuresRatiosAndPassesItsGoldens) {
  if (!on_path("povray")) GTEST_SKIP() << "povray is not on PATH (Debian package povray)";
  TempDir dir("raygate-povray");
  fs::create_directories(dir.path() / "tree");  // nothing to build: an empty tree
  const CliRun r = run_raygate({"run", "--adapter", "povray", "--worktree", "tree", "--suite", "ci",
                                "--scene", "tetra", "--scene", "balls", "--max-rounds", "3",
                                "--out", "results.json", "--no-store"},
                               dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const ResultsDocument doc = read_results(dir.path() / "results.json");
  ASSERT_EQ(doc.scenes.size(), 2u);
  EXPECT_EQ(doc.settings.metric, "cpu");
  EXPECT_EQ(fs::path(doc.settings.golden_dir.value_or("")).filename(), "povray");
  for (const char* id : {"tetra", "balls"}) {
    const SceneResult* scene = scene_of(doc, id);
    ASSERT_NE(scene, nullptr) << id;
    EXPECT_EQ(scene->status, SceneStatus::measured) << id;
    EXPECT_EQ(scene->runs.rounds.size(), 3u) << id;
    const RatioSummary* ratio = scene->ratio(Role::tracer);
    ASSERT_NE(ratio, nullptr) << id;
    EXPECT_GT(ratio->ratio, 0.0) << id;
    ASSERT_EQ(scene->images.size(), 1u) << id;
    const ImageCheck& image = scene->images.front();
    EXPECT_EQ(image.reference, ImageReference::golden) << id;
    EXPECT_EQ(image.verdict, ImageVerdict::pass) << id << ": " << image.error;
    EXPECT_EQ(image.expected.filename(), std::string(id) + ".png") << id;
    EXPECT_EQ(image.expected.parent_path().filename(), "povray") << id;
  }
}

// A results document of a run of adapter `my-tracer` whose tracer image of tetra is `image`.
ResultsDocument document_with_image(const fs::path& image) {
  ResultsDocument doc;
  doc.suite = "ci";
  doc.started_at = "2024-05-01T10:00:00Z";
  doc.baseline.version = "raygate-baseline 0.1.0 source-sha256:abc";
  doc.baseline.source_sha256 = "abc";
  RevisionRecord revision;
  revision.role = Role::tracer;
  revision.adapter_name = "my-tracer";
  revision.adapter_hash = std::string(64, 'a');
  revision.worktree.revision = "HEAD";
  revision.worktree.sha = std::string(40, 'b');
  doc.revisions.push_back(revision);
  SceneResult scene;
  scene.entry = {"tetra", "tetra", 6, 160, 160};
  scene.status = SceneStatus::measured;
  RunRecord warmup;
  warmup.ok = true;
  warmup.image = image;
  scene.runs.warmup["tracer"] = {warmup};
  doc.scenes.push_back(scene);
  return doc;
}

void write_png(const fs::path& path, int width, int height, float grey) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT));
  const float colour[3] = {grey, grey, grey};
  OIIO::ImageBufAlgo::fill(buf, colour);
  ASSERT_TRUE(buf.write(path.string(), OIIO::TypeDesc::UINT8));
}

TEST(GoldenBlessFromRun, CopiesTheRunsImageWithProvenance) {
  TempDir dir("raygate-bless");
  fs::create_directories(dir.path() / "run");
  write_png(dir.path() / "run" / "image.png", 160, 160, 0.5f);
  write_results(document_with_image(dir.path() / "run" / "image.png"), dir.path() / "r.json");

  const CliRun r =
      run_raygate({"golden", "bless", "--from-run", "r.json", "--golden-dir", "golden-mine"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("blessed   tetra"), std::string::npos) << r.out;
  const fs::path golden = dir.path() / "golden-mine";
  const GoldenManifest m = load_golden_manifest(golden);
  EXPECT_EQ(m.suite, "ci");
  ASSERT_EQ(m.entries.size(), 1u);
  const GoldenEntry& e = m.entries.front();
  EXPECT_EQ(e.id, "tetra");
  EXPECT_EQ(e.size, 6);
  EXPECT_EQ(e.width, 160);
  EXPECT_EQ(e.height, 160);
  EXPECT_EQ(e.sampling, "center");
  EXPECT_EQ(e.file, "tetra.png");
  EXPECT_EQ(e.sha256, sha256_file_hex(golden / "tetra.png"));
  EXPECT_EQ(read_file(golden / "tetra.png"), read_file(dir.path() / "run" / "image.png"));
  ASSERT_TRUE(m.tracer.has_value());
  EXPECT_EQ(m.tracer->adapter, "my-tracer");
  EXPECT_EQ(m.tracer->adapter_hash, std::string(64, 'a'));
  EXPECT_EQ(m.tracer->sha, std::string(40, 'b'));
  EXPECT_EQ(m.tracer->revision, "HEAD");
  EXPECT_EQ(m.tracer->results, (dir.path() / "r.json").string());

  // A baseline bless into a tracer's golden directory is refused.
  const CliRun baseline =
      run_raygate({"golden", "bless", "tetra", "--golden-dir", "golden-mine"}, dir);
  EXPECT_EQ(baseline.exit_code, 2) << baseline.out;
  EXPECT_NE(baseline.out.find("blessed from a run"), std::string::npos) << baseline.out;
}

TEST(GoldenBlessFromRun, RefusesUnknownScenesAndVanishedImagesWritingNothing) {
  TempDir dir("raygate-bless");
  write_results(document_with_image(dir.path() / "gone.png"), dir.path() / "r.json");
  const CliRun gone =
      run_raygate({"golden", "bless", "--from-run", "r.json", "--golden-dir", "g"}, dir);
  EXPECT_EQ(gone.exit_code, 2) << gone.out;
  EXPECT_NE(gone.out.find("is gone"), std::string::npos) << gone.out;

  write_png(dir.path() / "gone.png", 160, 160, 0.25f);
  const CliRun unknown = run_raygate(
      {"golden", "bless", "--from-run", "r.json", "--golden-dir", "g", "tetra", "balls"}, dir);
  EXPECT_EQ(unknown.exit_code, 2) << unknown.out;
  EXPECT_NE(unknown.out.find("scene 'balls' is not in"), std::string::npos) << unknown.out;
  EXPECT_FALSE(fs::exists(dir.path() / "g" / "manifest.json"));
  EXPECT_FALSE(fs::exists(dir.path() / "g" / "tetra.png"));

  const CliRun role = run_raygate(
      {"golden", "bless", "--from-run", "r.json", "--golden-dir", "g", "--role", "head"}, dir);
  EXPECT_EQ(role.exit_code, 2) << role.out;
  EXPECT_NE(role.out.find("no revision with role 'head'"), std::string::npos) << role.out;
}

}  // namespace
}  // namespace raygate::test

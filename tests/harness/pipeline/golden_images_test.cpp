// pipeline/golden_images: blessing a foreign tracer's images from a run, in process. What the run
// made is copied with its provenance; a document naming a scene "../x", an image that is not an
// image file, or an image that is gone blesses nothing at all; a write that fails midway (a
// full disk) leaves the old set and its manifest whole and in agreement.
#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>

#include <limits>
#include <string>
#include <vector>

#include "compare/golden.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/sha256.h"
#include "../core/file_size_limit.h"
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
  // The seventh sweep: a folder, device or FIFO where the image was called "gone".
  tracer_run(1).image = dir_.path() / "run";
  try {
    bless();
    ADD_FAILURE() << "a folder was blessed";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("is not a regular file"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(log_.lines.empty());
}

// The seventh sweep: a golden file that is a symbolic link was replaced by the blessed image;
// refused, as -o refuses one, and nothing blessed.
TEST_F(BlessFromRunTest, AGoldenThatIsALinkIsRefused) {
  bless();
  const fs::path elsewhere = dir_.path() / "elsewhere.ppm";
  write_file_atomically(elsewhere, "P3\n1 1\n255\n1 2 3\n");
  fs::remove(request_.golden_dir / "gears.ppm");
  fs::create_symlink(elsewhere, request_.golden_dir / "gears.ppm");
  try {
    bless();
    ADD_FAILURE() << "blessed over a link";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("gears.ppm is a symbolic link (to " + elsewhere.string()),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::is_symlink(request_.golden_dir / "gears.ppm"));
  EXPECT_EQ(read_file(elsewhere), "P3\n1 1\n255\n1 2 3\n");
}

// Sweep 12: an image with NaN pixels was blessed (the run's own check had failed it), and the
// golden then judged nothing. Refused before anything is written.
TEST_F(BlessFromRunTest, AnImageWithNanPixelsIsNotBlessed) {
  const float pixels[3] = {0.5f, std::numeric_limits<float>::quiet_NaN(), 0.25f};
  std::string pfm = "PF\n1 1\n-1.0\n";
  pfm.append(reinterpret_cast<const char*>(pixels), sizeof pixels);
  tracer_run(1).image = dir_.path() / "run" / "gears.pfm";
  write_file_atomically(tracer_run(1).image, pfm);
  try {
    bless();
    ADD_FAILURE() << "a NaN image was blessed";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("gears.pfm holds NaN or infinite values (the first at "
                                         "pixel (0, 0))"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(request_.golden_dir));
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

// A PPM of `side` x `side` pixels of one colour: real, and as large as asked for.
std::string ppm(int side, int value) {
  std::string text = "P3\n" + std::to_string(side) + " " + std::to_string(side) + "\n255\n";
  for (int i = 0; i < side * side; ++i) text += std::to_string(value) + " 0 0\n";
  return text;
}

// Every manifest entry's file exists and has the sha256 the manifest says.
void expect_manifest_matches_files(const fs::path& golden_dir) {
  const GoldenManifest manifest = load_golden_manifest(golden_dir);
  ASSERT_FALSE(manifest.entries.empty());
  for (const GoldenEntry& entry : manifest.entries) {
    ASSERT_TRUE(fs::exists(golden_dir / entry.file)) << entry.file;
    EXPECT_EQ(sha256_file_hex(golden_dir / entry.file), entry.sha256) << entry.file;
  }
}

// No temporary of a bless is left beside the golden folder.
bool leftover_temporaries(const fs::path& parent) {
  for (const auto& entry : fs::directory_iterator(parent)) {
    if (entry.path().filename().string().starts_with(".golden.")) return true;
  }
  return false;
}

TEST_F(BlessFromRunTest, AWriteFailingMidwayLeavesTheOldSetAndItsManifestInAgreement) {
  bless();
  const std::string old_balls = read_file(request_.golden_dir / "balls.ppm");
  const std::string old_manifest = read_file(request_.golden_dir / "manifest.json");
  // balls fits under the limit, gears does not: the new set fails after its first image.
  write_file_atomically(tracer_run(0).image, ppm(2, 200));
  write_file_atomically(tracer_run(1).image, ppm(100, 100));  // ~80 KB
  write_results(document_, request_.results);
  {
    const FileSizeLimit limit(16 * 1024);
    try {
      bless_goldens_from_run(request_, log_);
      ADD_FAILURE() << "the bless passed the file size limit";
    } catch (const WriteError& e) {
      EXPECT_EQ(std::string(e.what()), "cannot write " + request_.golden_dir.string() + ": " +
                                           std::strerror(EFBIG) +
                                           " (writing gears.ppm); the goldens there are "
                                           "unchanged");
    }
  }
  EXPECT_EQ(read_file(request_.golden_dir / "balls.ppm"), old_balls);
  EXPECT_EQ(read_file(request_.golden_dir / "manifest.json"), old_manifest);
  expect_manifest_matches_files(request_.golden_dir);
  EXPECT_FALSE(leftover_temporaries(dir_.path()));
}

TEST_F(BlessFromRunTest, ABlessReplacesTheWholeSetAndKeepsTheFolderOtherFiles) {
  bless();
  write_file_atomically(request_.golden_dir / "README.md", "goldens of make-nff\n");
  // A new file: OpenImageIO caches what it read under the old file's name.
  tracer_run(1).image = dir_.path() / "run" / "gears-again.ppm";
  write_file_atomically(tracer_run(1).image, ppm(3, 50));
  request_.scene_ids = {"gears"};
  bless();
  EXPECT_EQ(read_file(request_.golden_dir / "gears.ppm"), ppm(3, 50));
  EXPECT_EQ(read_file(request_.golden_dir / "README.md"), "goldens of make-nff\n");
  EXPECT_EQ(load_golden_manifest(request_.golden_dir).find("gears")->width, 3);
  expect_manifest_matches_files(request_.golden_dir);
  EXPECT_FALSE(leftover_temporaries(dir_.path()));
}

// The manifest is read by the one JSON reader: an entry whose sha256 is given twice (which
// copy would a verify believe?) or a width past a double's range is refused with where it is.
TEST_F(BlessFromRunTest, AManifestWithADuplicateKeyOrAHugeNumberIsRefusedWhereItIs) {
  bless();
  const fs::path manifest = request_.golden_dir / "manifest.json";
  const std::string text = read_file(manifest);
  const std::size_t sha = text.find("\"sha256\"");
  ASSERT_NE(sha, std::string::npos);
  write_file_atomically(manifest, text.substr(0, sha) + "\"sha256\": \"0\", " + text.substr(sha));
  try {
    load_golden_manifest(request_.golden_dir);
    ADD_FAILURE() << "a duplicate sha256 was taken";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(manifest.string() + ":"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(": $.images[0]: duplicate key 'sha256'"),
              std::string::npos)
        << e.what();
  }
  const std::size_t width = text.find("\"width\": ");
  ASSERT_NE(width, std::string::npos);
  write_file_atomically(manifest, text.substr(0, width) + "\"width\": 1e400, \"w\": " +
                                      text.substr(width + std::string("\"width\": ").size()));
  try {
    load_golden_manifest(request_.golden_dir);
    ADD_FAILURE() << "1e400 was taken";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("$.images[0].width: number 1e400 is out of range"),
              std::string::npos)
        << e.what();
  }
}

// A compare document has no tracer: the role asked for is missing, and the words list the
// roles the document has, for bless and verify alike.
TEST_F(BlessFromRunTest, AMissingRoleListsTheDocumentsRoles) {
  DocumentSpec spec;
  spec.sha = fake_sha(2);
  spec.kind = DocumentKind::compare;
  spec.roles = {Role::base, Role::head};
  spec.scenes = {{"balls"}};
  write_results(make_document(spec), request_.results);
  const std::string expected = request_.results.string() +
                               " has no revision with role 'tracer' (use --role base or --role "
                               "head)";
  try {
    bless_goldens_from_run(request_, log_);
    ADD_FAILURE() << "blessed";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
  try {
    verify_goldens_from_run(request_, dir_.path() / "evidence", log_);
    ADD_FAILURE() << "verified";
  } catch (const UsageError& e) {
    EXPECT_EQ(std::string(e.what()), expected);
  }
}

}  // namespace
}  // namespace raygate::test

// check_against_golden on the shipped goldens: a picture of the golden's own scene settings is
// compared (pass, or fail with evidence); no golden, or a golden of other settings under the
// same id (another suite's scene), is "missing" with the reason, never a failed comparison. An
// unreadable image (garbage, a truncated PNG) or one with NaN pixels fails; which goldens judge
// which adapter.
#include "compare/image_check.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "core/fs.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;
using ::testing::HasSubstr;

const fs::path kGoldenRoot = fs::path(RAYGATE_SOURCE_DIR) / "golden";
const fs::path kGolden = kGoldenRoot / "raygate-baseline";

class ImageCheckTest : public ::testing::Test {
 protected:
  // What the ci suite renders for tetra, the settings its shipped golden was made with.
  GoldenEntry ci_tetra() const {
    const GoldenEntry* entry = manifest_.find("tetra");
    EXPECT_NE(entry, nullptr);
    return GoldenEntry{"tetra",         entry->scene, entry->size, entry->width, entry->height,
                       entry->sampling, {},           {},          {},           {}};
  }

  ImageCheck check(const fs::path& actual, const GoldenEntry& rendered) const {
    return check_against_golden(Role::tracer, actual, kGolden, manifest_, rendered, {},
                                dir_.path() / "evidence");
  }

  TempDir dir_;
  GoldenManifest manifest_ = load_golden_manifest(kGolden);
};

TEST_F(ImageCheckTest, SameSettingsAndPixelsPass) {
  const ImageCheck c = check(kGolden / "tetra.png", ci_tetra());
  EXPECT_EQ(c.verdict, ImageVerdict::pass) << c.error;
  ASSERT_TRUE(c.metrics);
  EXPECT_TRUE(c.metrics->identical());
  EXPECT_EQ(c.reference, ImageReference::golden);
  EXPECT_EQ(c.expected, kGolden / "tetra.png");
}

TEST_F(ImageCheckTest, UnspecifiedResolutionAndSamplingDoNotPreventTheCheck) {
  GoldenEntry rendered = ci_tetra();
  rendered.width = rendered.height = 0;  // the scene's own resolution
  rendered.sampling.clear();
  EXPECT_EQ(check(kGolden / "tetra.png", rendered).verdict, ImageVerdict::pass);
}

TEST_F(ImageCheckTest, ChangedPixelsFailWithEvidence) {
  OIIO::ImageBuf image((kGolden / "tetra.png").string());
  ASSERT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::FLOAT));
  const float white[3] = {1, 1, 1};
  for (int x = 0; x < 40; ++x) image.setpixel(x, 7, white);
  const fs::path actual = dir_.path() / "tetra.png";
  ASSERT_TRUE(image.write(actual.string(), OIIO::TypeDesc::UINT8));
  const ImageCheck c = check(actual, ci_tetra());
  EXPECT_EQ(c.verdict, ImageVerdict::fail);
  ASSERT_EQ(c.evidence.size(), 3u);
  for (const fs::path& evidence : c.evidence) EXPECT_TRUE(fs::exists(evidence)) << evidence;
}

// A manifest whose hashes are all zeros (or any golden edited after blessing) judges nothing:
// the check could not be made (error, exit 3), naming the file, not "identical".
TEST_F(ImageCheckTest, AGoldenThatIsNotItsManifestsHashIsAnError) {
  GoldenManifest zeros = manifest_;
  for (GoldenEntry& e : zeros.entries) e.sha256 = std::string(64, '0');
  const ImageCheck c = check_against_golden(Role::tracer, kGolden / "tetra.png", kGolden, zeros,
                                            ci_tetra(), {}, dir_.path() / "evidence");
  EXPECT_EQ(c.verdict, ImageVerdict::error);
  EXPECT_FALSE(c.metrics);
  EXPECT_NE(c.error.find((kGolden / "tetra.png").string() + ": its SHA-256 "), std::string::npos)
      << c.error;
  EXPECT_NE(c.error.find("changed after it was blessed"), std::string::npos) << c.error;
  EXPECT_EQ(check_detail(c), c.error);
}

// A manifest that lists a golden at a size it is not (hand-edited: width 64 for a 160x160
// image) matched renders of that size to a picture of another: it judges nothing.
TEST_F(ImageCheckTest, AGoldenOfAnotherSizeThanItsManifestSaysIsAnError) {
  GoldenManifest edited = manifest_;
  GoldenEntry rendered = ci_tetra();
  for (GoldenEntry& e : edited.entries) {
    if (e.id == "tetra") e.width = rendered.width = e.width / 2;
  }
  const ImageCheck c = check_against_golden(Role::tracer, kGolden / "tetra.png", kGolden, edited,
                                            rendered, {}, dir_.path() / "evidence");
  EXPECT_EQ(c.verdict, ImageVerdict::error);
  EXPECT_NE(c.error.find("but the manifest lists it at"), std::string::npos) << c.error;
}

TEST_F(ImageCheckTest, NoGoldenForTheIdIsMissing) {
  GoldenEntry rendered = ci_tetra();
  rendered.id = "tetra-s2";
  const ImageCheck c = check(kGolden / "tetra.png", rendered);
  EXPECT_EQ(c.verdict, ImageVerdict::missing);
  EXPECT_NE(c.error.find("no golden image for 'tetra-s2'"), std::string::npos) << c.error;
  EXPECT_FALSE(c.metrics);
}

// A tracer that exits 0 but writes garbage has failed on the scene (exit 1), golden or not; the
// message is one line, whatever the image library said.
TEST_F(ImageCheckTest, UnreadableImageFailsEvenWithoutAGolden) {
  const fs::path garbage = dir_.path() / "image.ppm";
  write_file_atomically(garbage, "not an image\n");
  GoldenEntry rendered = ci_tetra();
  rendered.id = "tetra-s2";
  const ImageCheck c = check(garbage, rendered);
  EXPECT_EQ(c.verdict, ImageVerdict::fail);
  EXPECT_TRUE(c.failed());
  EXPECT_NE(c.error.find(garbage.string() + ": cannot read image"), std::string::npos) << c.error;
  EXPECT_EQ(c.error.find('\n'), std::string::npos) << c.error;
  rendered = ci_tetra();
  rendered.size = 2;
  EXPECT_EQ(check(garbage, rendered).verdict, ImageVerdict::fail);
  // With a golden to compare with:
  EXPECT_EQ(check(garbage, ci_tetra()).verdict, ImageVerdict::fail);
}

// A PNG cut short: libpng's several lines of complaint become one.
TEST_F(ImageCheckTest, TruncatedPngFailsWithOneLine) {
  const std::string png = read_file(kGolden / "tetra.png");
  const fs::path truncated = dir_.path() / "tetra.png";
  write_file_atomically(truncated, png.substr(0, png.size() / 2));
  const GoldenEntry other{"other", "tetra", 2, 0, 0, "", {}, {}, {}, {}};
  for (const GoldenEntry& rendered : {ci_tetra(), other}) {
    const ImageCheck c = check(truncated, rendered);
    EXPECT_EQ(c.verdict, ImageVerdict::fail) << c.error;
    EXPECT_NE(c.error.find("cannot read image"), std::string::npos) << c.error;
    EXPECT_EQ(c.error.find('\n'), std::string::npos) << c.error;
  }
  const ImageCheck against_base =
      check_image(Role::head, ImageReference::base, truncated, kGolden / "tetra.png", {},
                  dir_.path() / "evidence", "tetra.head-vs-base");
  EXPECT_EQ(against_base.verdict, ImageVerdict::fail) << against_base.error;
}

// The golden as floats, with NaN in `nan_pixels` pixels of row 5, written as `name`.
fs::path with_nan(const TempDir& dir, const std::string& name, int nan_pixels) {
  OIIO::ImageBuf image((kGolden / "tetra.png").string());
  EXPECT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBuf rgb(
      OIIO::ImageSpec(image.spec().width, image.spec().height, 3, OIIO::TypeDesc::FLOAT));
  OIIO::ImageBufAlgo::copy(rgb, image);
  for (int x = 0; x < nan_pixels; ++x) {
    const float nan[3] = {std::nanf(""), 0.5f, 0.5f};
    rgb.setpixel(10 + x, 5, nan);
  }
  const fs::path path = dir.path() / name;
  EXPECT_TRUE(rgb.write(path.string(), OIIO::TypeDesc::FLOAT)) << rgb.geterror();
  return path;
}

// An 8x8 grey PFM (the float format tracers dump), written by hand: this OpenImageIO reads PFM
// but cannot write it. NaN in red of the first `nan_pixels` pixels of the top row.
fs::path grey_pfm(const TempDir& dir, const std::string& name, int nan_pixels) {
  constexpr int kSize = 8;
  std::string bytes = "PF\n8 8\n-1.0\n";  // negative scale: little-endian floats
  for (int y = kSize - 1; y >= 0; --y) {  // rows bottom to top
    for (int x = 0; x < kSize; ++x) {
      const float rgb[3] = {y == 0 && x < nan_pixels ? std::nanf("") : 0.5f, 0.5f, 0.5f};
      bytes.append(reinterpret_cast<const char*>(rgb), sizeof rgb);
    }
  }
  write_file_atomically(dir.path() / name, bytes);
  return dir.path() / name;
}

TEST_F(ImageCheckTest, NanPixelsOfAPfmAreCountedAndFail) {
  const ImageCheck c =
      check_image(Role::tracer, ImageReference::golden, grey_pfm(dir_, "nan.pfm", 3),
                  grey_pfm(dir_, "good.pfm", 0), {}, dir_.path() / "evidence", "grey");
  EXPECT_EQ(c.verdict, ImageVerdict::fail) << c.error;
  ASSERT_TRUE(c.metrics);
  EXPECT_EQ(c.metrics->nonfinite_pixels, 3);
  EXPECT_EQ(summarize(*c.metrics), "3 NaN/Inf pixels of 64, first at (0,0)");
}

TEST_F(ImageCheckTest, NanPixelsAreCountedAndFail) {
  for (const char* name : {"nan.exr"}) {
    const fs::path nan = with_nan(dir_, name, 7);
    const ImageCheck c = check(nan, ci_tetra());
    EXPECT_EQ(c.verdict, ImageVerdict::fail) << name;
    ASSERT_TRUE(c.metrics) << name;
    EXPECT_EQ(c.metrics->nonfinite_pixels, 7) << name;
    const std::string text = summarize(*c.metrics);
    EXPECT_EQ(text, "7 NaN/Inf pixels of 25600, first at (10,5)") << name;
    EXPECT_EQ(text.find("max nan"), std::string::npos) << text;
  }
  // Without a golden too.
  const ImageCheck alone =
      check_against_golden(Role::tracer, with_nan(dir_, "n.exr", 2), dir_.path() / "none",
                           GoldenManifest{}, ci_tetra(), {}, dir_.path() / "evidence");
  EXPECT_EQ(alone.verdict, ImageVerdict::fail);
  EXPECT_NE(alone.error.find("2 NaN/Inf pixels"), std::string::npos) << alone.error;
}

// NaN in the reference (base's image) is no reference: the check could not be made.
TEST_F(ImageCheckTest, NanInTheReferenceIsAnError) {
  const ImageCheck c = check_image(Role::head, ImageReference::base, kGolden / "tetra.png",
                                   with_nan(dir_, "base.exr", 3), {}, dir_.path() / "evidence",
                                   "tetra.head-vs-base");
  EXPECT_EQ(c.verdict, ImageVerdict::error);
  EXPECT_NE(c.error.find("the reference has 3 NaN/Inf pixels"), std::string::npos) << c.error;
  EXPECT_FALSE(c.metrics) << "no comparison happened, so no numbers that look like one";
}

// A tracer with no goldens: the same words for every scene, so a report can say them once, and
// a readable image is not failed for it.
TEST_F(ImageCheckTest, NoGoldensAtAllSaysTheSameForEveryScene) {
  const fs::path empty = dir_.path() / "golden" / "my-tracer";
  GoldenEntry balls = ci_tetra();
  balls.id = balls.scene = "balls";
  const ImageCheck a = check_against_golden(Role::tracer, kGolden / "tetra.png", empty,
                                            GoldenManifest{}, ci_tetra(), {}, dir_.path());
  balls.width = balls.height = 128;  // balls.png's size
  const ImageCheck b = check_against_golden(Role::tracer, kGolden / "balls.png", empty,
                                            GoldenManifest{}, balls, {}, dir_.path());
  EXPECT_EQ(a.verdict, ImageVerdict::missing);
  EXPECT_FALSE(a.failed());
  EXPECT_FALSE(a.metrics);
  EXPECT_EQ(a.error, b.error);
  EXPECT_EQ(a.error, "no goldens: " + empty.string() + " does not exist");
  // A folder that is there but holds no set yet says so: a mistyped --golden-dir is told apart.
  fs::create_directories(empty);
  const ImageCheck c = check_against_golden(Role::tracer, kGolden / "tetra.png", empty,
                                            GoldenManifest{}, ci_tetra(), {}, dir_.path());
  EXPECT_EQ(c.error, "no goldens in " + empty.string() + " (none blessed yet)");
}

TEST_F(ImageCheckTest, GoldenOfAnotherSizeFactorIsNotCompared) {
  GoldenEntry rendered = ci_tetra();
  rendered.size = 2;
  const ImageCheck c = check(kGolden / "tetra.png", rendered);
  EXPECT_EQ(c.verdict, ImageVerdict::missing);
  EXPECT_FALSE(c.metrics);
  EXPECT_NE(c.error.find("is tetra size 6 at 160x160, center sampling, but this suite renders "
                         "tetra size 2 at 160x160"),
            std::string::npos)
      << c.error;
  // Whose goldens they are is not known here (a tracer's are blessed from a run, the baseline's
  // from a suite): the advice is the directory, which both need.
  EXPECT_NE(c.error.find("bless this suite's goldens into a directory of their own (--golden-dir"),
            std::string::npos)
      << c.error;
}

// The tenth sweep: a manifest entry edited (width 160 to 161) made run pass the image unchecked,
// "no golden". Of the suite being measured, it is a golden that cannot judge (ERROR, exit 3); of
// another suite (a calibrated one beside the ci goldens), it stays a note.
TEST_F(ImageCheckTest, AnEditedEntryOfTheSuiteMeasuredIsAnError) {
  GoldenManifest edited = manifest_;
  for (GoldenEntry& entry : edited.entries) {
    if (entry.id == "tetra") entry.width = 161;
  }
  GoldenEntry rendered = ci_tetra();
  rendered.rendering_suite = edited.suite;
  const ImageCheck same_suite = check_against_golden(Role::tracer, kGolden / "tetra.png", kGolden,
                                                     edited, rendered, {}, dir_.path());
  EXPECT_EQ(same_suite.verdict, ImageVerdict::error);
  EXPECT_THAT(same_suite.error, HasSubstr("the entry of 'tetra' is tetra size 6 at 161x160"));
  EXPECT_THAT(same_suite.error, HasSubstr("(edited after bless?)"));
  rendered.rendering_suite = edited.suite + "-calibrated";
  const ImageCheck other_suite = check_against_golden(Role::tracer, kGolden / "tetra.png", kGolden,
                                                      edited, rendered, {}, dir_.path());
  EXPECT_EQ(other_suite.verdict, ImageVerdict::missing);
}

// The eleventh sweep: a golden that is a symbolic link loop threw "filesystem error: status: Too
// many levels of symbolic links" over the whole run, whose document was then never written.
TEST_F(ImageCheckTest, AGoldenThatIsALinkLoopIsAnErrorOfItsScene) {
  const fs::path loop_dir = dir_.path() / "loop";
  fs::create_directories(loop_dir);
  const std::string file = manifest_.find("tetra")->file;
  fs::create_symlink(file, loop_dir / file);  // links to itself
  const ImageCheck c = check_against_golden(Role::tracer, kGolden / "tetra.png", loop_dir,
                                            manifest_, ci_tetra(), {}, dir_.path());
  EXPECT_EQ(c.verdict, ImageVerdict::error);
  EXPECT_THAT(c.error, HasSubstr("golden file cannot be read"));
}

// A grey `width` x `height` PNG, written as `name`.
fs::path grey_png(const TempDir& dir, const std::string& name, int width, int height) {
  OIIO::ImageBuf image(OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8));
  const float grey[3] = {0.5f, 0.5f, 0.5f};
  OIIO::ImageBufAlgo::fill(image, grey);
  const fs::path path = dir.path() / name;
  EXPECT_TRUE(image.write(path.string())) << image.geterror();
  return path;
}

TEST_F(ImageCheckTest, GoldenOfAnotherResolutionOrSamplingIsNotCompared) {
  GoldenEntry smaller = ci_tetra();
  smaller.width = smaller.height = 64;
  EXPECT_EQ(check(grey_png(dir_, "small.png", 64, 64), smaller).verdict, ImageVerdict::missing);
  GoldenEntry corners = ci_tetra();
  corners.sampling = "corners";
  EXPECT_EQ(check(kGolden / "tetra.png", corners).verdict, ImageVerdict::missing);
}

// An image of another size than the scene renders is the tracer's failure even with nothing to
// compare it with (issue 40: a 10x10 image for a 48x48 scene passed a run without goldens).
TEST_F(ImageCheckTest, ImageOfAnotherSizeThanTheSceneFailsWithoutAGolden) {
  const fs::path tiny = grey_png(dir_, "tiny.png", 10, 10);
  GoldenEntry rendered = ci_tetra();
  rendered.id = "tetra-s2";  // no golden of that id
  rendered.width = rendered.height = 48;
  for (const ImageCheck& c :
       {check(tiny, rendered), check_against_golden(Role::tracer, tiny, dir_.path() / "none",
                                                    GoldenManifest{}, rendered, {}, dir_.path())}) {
    EXPECT_EQ(c.verdict, ImageVerdict::fail) << c.error;
    EXPECT_NE(c.error.find("tiny.png: the image is 10x10, but the scene renders at 48x48"),
              std::string::npos)
        << c.error;
  }
  rendered.width = rendered.height = 10;
  EXPECT_EQ(check(tiny, rendered).verdict, ImageVerdict::missing);
  rendered.width = rendered.height = 0;  // the scene's own resolution, not known here
  EXPECT_EQ(check(tiny, rendered).verdict, ImageVerdict::missing);
}

// A run folder deleted while raygate ran: nobody can tell what the tracer wrote, so the check
// could not be made (error, exit 3), where a tracer that wrote no image in its folder fails.
TEST_F(ImageCheckTest, AnImageWhoseRunFolderIsGoneIsAnErrorNotAFailure) {
  const fs::path gone = dir_.path() / "runs" / "r1" / "tetra" / "tracer" / "image.png";
  GoldenEntry other = ci_tetra();
  other.id = "tetra-s2";
  for (const ImageCheck& c :
       {check(gone, ci_tetra()), check(gone, other),
        check_image(Role::head, ImageReference::base, gone, kGolden / "tetra.png", {},
                    dir_.path() / "evidence", "tetra.head-vs-base")}) {
    EXPECT_EQ(c.verdict, ImageVerdict::error) << c.error;
    EXPECT_NE(c.error.find("the run's folder is gone"), std::string::npos) << c.error;
  }
  fs::create_directories(gone.parent_path());  // the folder is there, the image is not
  EXPECT_EQ(check(gone, ci_tetra()).verdict, ImageVerdict::fail);
}

// Goldens belong to an adapter: the baseline's judge the baseline and its bbox control, never
// another tracer, which gets golden/<adapter>/ whether or not it exists yet.
TEST(AdapterGoldens, EachAdapterHasItsOwnAndTheBaselineSharesOnlyWithItsVariants) {
  EXPECT_EQ(adapter_golden_dir(kGoldenRoot, "raygate-baseline"), kGolden);
  EXPECT_EQ(adapter_golden_dir(kGoldenRoot, "raygate-baseline-bbox"), kGolden);
  EXPECT_EQ(adapter_golden_dir(kGoldenRoot, "povray"), kGoldenRoot / "povray");
  EXPECT_EQ(adapter_golden_dir(kGoldenRoot, "cmake-nff"), kGoldenRoot / "cmake-nff");
  EXPECT_EQ(golden_owner(load_golden_manifest(kGolden)), "raygate-baseline");
  EXPECT_EQ(golden_owner(load_golden_manifest(kGoldenRoot / "cmake-nff")), "none");

  TempDir dir;
  GoldenManifest shared;
  shared.suite = "ci";
  shared.shared_with = {"fast-variant"};
  shared.upsert(
      {"tetra", "tetra", 6, 160, 160, "center", "none", "tetra.png", std::string(64, 'f'), {}});
  save_golden_manifest(shared, dir.path() / "slow");
  EXPECT_EQ(load_golden_manifest(dir.path() / "slow").shared_with, shared.shared_with);
  EXPECT_EQ(adapter_golden_dir(dir.path(), "fast-variant"), dir.path() / "slow");
  EXPECT_EQ(adapter_golden_dir(dir.path(), "other"), dir.path() / "other");
  EXPECT_EQ(adapter_golden_dir(dir.path() / "absent", "other"), dir.path() / "absent" / "other");
}

}  // namespace
}  // namespace raygate

// check_against_golden on the shipped goldens: a picture of the golden's own scene settings is
// compared (pass, or fail with evidence); no golden, or a golden of other settings under the
// same id (another suite's scene), is "missing" with the reason, never a failed comparison.
#include "compare/image_check.h"

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>

#include "core/fs.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

const fs::path kGolden = fs::path(RAYGATE_SOURCE_DIR) / "golden";

class ImageCheckTest : public ::testing::Test {
 protected:
  // What the ci suite renders for tetra, the settings its shipped golden was made with.
  GoldenEntry ci_tetra() const {
    const GoldenEntry* entry = manifest_.find("tetra");
    EXPECT_NE(entry, nullptr);
    return GoldenEntry{"tetra", entry->scene, entry->size, entry->width, entry->height,
                       entry->sampling, {}, {}, {}};
  }

  ImageCheck check(const fs::path& actual, const GoldenEntry& rendered) const {
    return check_against_golden("tracer", actual, kGolden, manifest_, rendered, {},
                                dir_.path() / "evidence");
  }

  TempDir dir_;
  GoldenManifest manifest_ = load_golden_manifest(kGolden);
};

TEST_F(ImageCheckTest, SameSettingsAndPixelsPass) {
  const ImageCheck c = check(kGolden / "tetra.png", ci_tetra());
  EXPECT_EQ(c.verdict, "pass") << c.error;
  ASSERT_TRUE(c.metrics);
  EXPECT_TRUE(c.metrics->identical());
  EXPECT_EQ(c.reference, "golden");
  EXPECT_EQ(c.expected, kGolden / "tetra.png");
}

TEST_F(ImageCheckTest, UnspecifiedResolutionAndSamplingDoNotPreventTheCheck) {
  GoldenEntry rendered = ci_tetra();
  rendered.width = rendered.height = 0;  // the scene's own resolution
  rendered.sampling.clear();
  EXPECT_EQ(check(kGolden / "tetra.png", rendered).verdict, "pass");
}

TEST_F(ImageCheckTest, ChangedPixelsFailWithEvidence) {
  OIIO::ImageBuf image((kGolden / "tetra.png").string());
  ASSERT_TRUE(image.read(0, 0, true, OIIO::TypeDesc::FLOAT));
  const float white[3] = {1, 1, 1};
  for (int x = 0; x < 40; ++x) image.setpixel(x, 7, white);
  const fs::path actual = dir_.path() / "tetra.png";
  ASSERT_TRUE(image.write(actual.string(), OIIO::TypeDesc::UINT8));
  const ImageCheck c = check(actual, ci_tetra());
  EXPECT_EQ(c.verdict, "fail");
  ASSERT_EQ(c.evidence.size(), 3u);
  for (const fs::path& evidence : c.evidence) EXPECT_TRUE(fs::exists(evidence)) << evidence;
}

TEST_F(ImageCheckTest, NoGoldenForTheIdIsMissing) {
  GoldenEntry rendered = ci_tetra();
  rendered.id = "tetra-s2";
  const ImageCheck c = check(kGolden / "tetra.png", rendered);
  EXPECT_EQ(c.verdict, "missing");
  EXPECT_NE(c.error.find("no golden image for 'tetra-s2'"), std::string::npos) << c.error;
  EXPECT_FALSE(c.metrics);
}

TEST_F(ImageCheckTest, UnreadableImageIsAnErrorEvenWithoutAGolden) {
  const fs::path garbage = dir_.path() / "image.png";
  write_file_atomically(garbage, "not an image\n");
  GoldenEntry rendered = ci_tetra();
  rendered.id = "tetra-s2";
  const ImageCheck c = check(garbage, rendered);
  EXPECT_EQ(c.verdict, "error");
  EXPECT_NE(c.error.find(garbage.string() + ": cannot read image"), std::string::npos) << c.error;
  EXPECT_NE(c.error.find("no golden image for 'tetra-s2'"), std::string::npos) << c.error;
  rendered = ci_tetra();
  rendered.size = 2;
  EXPECT_EQ(check(garbage, rendered).verdict, "error");
}

TEST_F(ImageCheckTest, GoldenOfAnotherSizeFactorIsNotCompared) {
  GoldenEntry rendered = ci_tetra();
  rendered.size = 2;
  const ImageCheck c = check(kGolden / "tetra.png", rendered);
  EXPECT_EQ(c.verdict, "missing");
  EXPECT_FALSE(c.metrics);
  EXPECT_NE(c.error.find("is tetra size 6 at 160x160, center sampling, but this suite renders "
                         "tetra size 2 at 160x160"),
            std::string::npos)
      << c.error;
  EXPECT_NE(c.error.find("raygate golden bless --suite"), std::string::npos) << c.error;
}

TEST_F(ImageCheckTest, GoldenOfAnotherResolutionOrSamplingIsNotCompared) {
  GoldenEntry smaller = ci_tetra();
  smaller.width = smaller.height = 64;
  EXPECT_EQ(check(kGolden / "tetra.png", smaller).verdict, "missing");
  GoldenEntry corners = ci_tetra();
  corners.sampling = "corners";
  EXPECT_EQ(check(kGolden / "tetra.png", corners).verdict, "missing");
}

}  // namespace
}  // namespace raygate

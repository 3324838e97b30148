// The Monte Carlo check as an ImageCheck: verdicts map onto the image verdicts the gate and
// reports know (inconclusive is a warn), a broken image of the tracer fails, a broken reference
// is an error, evidence (the runs' means and the tile map) is written on failure, and a tracer
// whose runs are all the same image is told so.
#include "compare/noisy_image_check.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "compare/noisy_image_files.h"
#include "core/fs.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;

// `runs` renders of a flat grey image times `factor`, gamma noise of relative sd 0.3.
std::vector<fs::path> renders(const fs::path& dir, const std::string& stem, int runs, double factor,
                              std::mt19937_64& rng) {
  std::gamma_distribution<double> noise(1 / 0.09, 0.09);
  std::vector<fs::path> files;
  for (int i = 0; i < runs; ++i) {
    RgbImage image{32, 32, std::vector<float>(32 * 32 * 3)};
    for (float& v : image.rgb) v = static_cast<float>(0.5 * factor * noise(rng));
    files.push_back(dir / (stem + std::to_string(i) + ".exr"));
    write_rgb_image(image, files.back());
  }
  return files;
}

TEST(NoisyImageCheck, VerdictsMapOntoImageVerdicts) {
  EXPECT_EQ(to_image_verdict(NoisyVerdict::pass), ImageVerdict::pass);
  EXPECT_EQ(to_image_verdict(NoisyVerdict::fail), ImageVerdict::fail);
  EXPECT_EQ(to_image_verdict(NoisyVerdict::inconclusive), ImageVerdict::warn);
  EXPECT_DOUBLE_EQ(noisy_thresholds_for(4).alpha, kNoisyFamilyAlpha / 4);
  EXPECT_DOUBLE_EQ(noisy_thresholds_for(0).alpha, kNoisyFamilyAlpha);
}

TEST(NoisyImageCheck, ABiasedHeadFailsWithEvidence) {
  const TempDir dir;
  std::mt19937_64 rng(41);
  const ImageCheck check = check_noisy_images(
      Role::head, ImageReference::base, renders(dir.path(), "head", 6, 0.9, rng), renders(dir.path(), "base", 6, 1.0, rng),
      noisy_thresholds_for(1), dir.path() / "evidence", "s.head-vs-base");
  EXPECT_EQ(check.verdict, ImageVerdict::fail) << check.error;
  EXPECT_FALSE(check.metrics.has_value());
  EXPECT_EQ(check.error.rfind("fail (biased): ", 0), 0u) << check.error;
  ASSERT_EQ(check.evidence.size(), 3u);
  EXPECT_EQ(check.evidence[2].filename(), "s.head-vs-base.tiles.png");
  for (const fs::path& file : check.evidence) EXPECT_TRUE(fs::exists(file)) << file;
}

TEST(NoisyImageCheck, SameImageOtherSeedsPasses) {
  const TempDir dir;
  std::mt19937_64 rng(43);
  const ImageCheck check = check_noisy_images(
      Role::head, ImageReference::base, renders(dir.path(), "head", 6, 1.0, rng), renders(dir.path(), "base", 6, 1.0, rng),
      noisy_thresholds_for(1), dir.path() / "evidence", "s");
  EXPECT_EQ(check.verdict, ImageVerdict::pass) << check.error;
  EXPECT_TRUE(check.evidence.empty());
}

TEST(NoisyImageCheck, ANaNInOneOfTheTracersRunsFails) {
  const TempDir dir;
  std::mt19937_64 rng(47);
  std::vector<fs::path> head = renders(dir.path(), "head", 3, 1.0, rng);
  RgbImage broken = read_rgb_image(head[1]);
  broken.rgb[(5 * 32 + 7) * 3 + 1] = std::numeric_limits<float>::quiet_NaN();
  write_rgb_image(broken, head[1]);
  const ImageCheck check = check_noisy_images(Role::head, ImageReference::base, head,
                                              renders(dir.path(), "base", 3, 1.0, rng),
                                              noisy_thresholds_for(1), dir.path(), "s");
  EXPECT_EQ(check.verdict, ImageVerdict::fail);
  EXPECT_NE(check.error.find("head1.exr: NaN/Inf pixels, first at (7,5)"), std::string::npos)
      << check.error;
}

TEST(NoisyImageCheck, AnUnreadableReferenceIsAnError) {
  const TempDir dir;
  std::mt19937_64 rng(53);
  write_file_atomically(dir.path() / "base0.exr", "not an image");
  const ImageCheck check =
      check_noisy_images(Role::head, ImageReference::base, renders(dir.path(), "head", 3, 1.0, rng),
                         {dir.path() / "base0.exr"}, noisy_thresholds_for(1), dir.path(), "s");
  EXPECT_EQ(check.verdict, ImageVerdict::error);
  EXPECT_NE(check.error.find("base0.exr: cannot read image"), std::string::npos) << check.error;
}

TEST(NoisyImageCheck, RunsThatAreAllTheSameImageAreNoted) {
  const TempDir dir;
  std::mt19937_64 rng(59);
  const std::vector<fs::path> one = renders(dir.path(), "same", 1, 1.0, rng);
  const ImageCheck check = check_noisy_images(Role::head, ImageReference::base, {one[0], one[0], one[0]},
                                              renders(dir.path(), "base", 4, 1.0, rng),
                                              noisy_thresholds_for(1), dir.path(), "s");
  EXPECT_NE(check.error.find("runs' images are identical: is {seed} reaching"), std::string::npos)
      << check.error;
}

}  // namespace
}  // namespace raygate

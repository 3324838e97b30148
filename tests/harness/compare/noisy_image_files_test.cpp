// The Monte Carlo check's files: float images written and read back exactly (the golden's mean
// and variance), the statistics of a set of image files, and what the statistical check costs
// against the per-pixel one on the same files (printed; docs/monte-carlo-images.md quotes it).
#include "compare/noisy_image_files.h"

#include <OpenImageIO/imagebuf.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <random>

#include "compare/golden.h"
#include "compare/image_compare.h"
#include "compare/noisy_image_compare.h"
#include "core/fs.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;
namespace OIIO = OIIO_NAMESPACE;

RgbImage noisy(int size, std::mt19937_64& rng) {
  std::gamma_distribution<double> noise(4.0, 0.25);  // mean 1, relative sd 0.5
  RgbImage image{size, size, {}};
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double v = 0.1 + 0.8 * x / size;
      for (int c = 0; c < 3; ++c) image.rgb.push_back(static_cast<float>(v * noise(rng)));
    }
  }
  return image;
}

std::vector<fs::path> write_runs(const fs::path& dir, const std::string& stem, int runs, int size,
                                 std::mt19937_64& rng) {
  std::vector<fs::path> files;
  for (int i = 0; i < runs; ++i) {
    files.push_back(dir / (stem + std::to_string(i) + ".exr"));
    write_rgb_image(noisy(size, rng), files.back());
  }
  return files;
}

TEST(NoisyImageFiles, StatisticsSurviveTheGoldenFilesExactly) {
  const TempDir dir;
  std::mt19937_64 rng(3);
  const NoisyImageStats stats = stats_of_images(write_runs(dir.path(), "run", 4, 24, rng));
  EXPECT_EQ(stats.runs, 4);
  write_stats_images(stats, dir.path() / "m.exr", dir.path() / "v.exr");
  const NoisyImageStats back =
      read_stats_images(dir.path() / "m.exr", dir.path() / "v.exr", stats.runs, stats.inflation);
  EXPECT_EQ(back.width, 24);
  EXPECT_EQ(back.mean, stats.mean);
  EXPECT_EQ(back.variance, stats.variance);
  EXPECT_EQ(back.inflation, stats.inflation);
}

// A Monte Carlo golden's statistics live in its manifest entry's "noise" object and come back
// the same; an entry that claims fewer than 2 runs (no variance to judge with) is read as it is
// and refused as a golden that cannot judge (a check error, like more than 10^6).
TEST(NoisyImageFiles, GoldenManifestKeepsTheNoiseOfEachEntry) {
  const TempDir dir;
  GoldenManifest manifest;
  manifest.suite = "ci";
  manifest.entries.push_back(
      {"balls", "balls", 1, 48, 48, "center", "", "balls.mean.exr", std::string(64, 'a')});
  manifest.entries.push_back(
      {"gears", "gears", 1, 48, 48, "center", "", "gears.png", std::string(64, 'c')});
  manifest.noise["balls"] = {
      8, "balls.variance.exr", std::string(64, 'e'), {{8, 1.02}, {kWholeImage, 1.5}}};
  save_golden_manifest(manifest, dir.path());
  const GoldenManifest back = load_golden_manifest(dir.path());
  ASSERT_EQ(back.noise.size(), 1u);
  EXPECT_EQ(back.noise.at("balls"), manifest.noise.at("balls"));
  EXPECT_EQ(back.noise.count("gears"), 0u);
  EXPECT_EQ(golden_noise_problem(back.noise.at("balls"), "m"), std::nullopt);

  std::string text = read_file(dir.path() / "manifest.json");
  const std::string runs = "\"runs\": 8";
  text.replace(text.find(runs), runs.size(), "\"runs\": 1");
  write_file_atomically(dir.path() / "manifest.json", text);
  const GoldenNoise one_run = load_golden_manifest(dir.path()).noise.at("balls");
  EXPECT_EQ(golden_noise_problem(one_run, "m: 'balls'"),
            "m: 'balls': noise.runs 1 is not a number of runs (2 to 1000000)");
  // No factor at all (`"inflation": []`): every tile judged as if its pixels' noise were
  // independent, which bless never writes.
  GoldenNoise no_inflation = manifest.noise.at("balls");
  no_inflation.inflation.clear();
  ASSERT_TRUE(golden_noise_problem(no_inflation, "m: 'balls'"));
  EXPECT_NE(golden_noise_problem(no_inflation, "m: 'balls'")->find("noise.inflation is empty"),
            std::string::npos);
}

TEST(NoisyImageFiles, ImagesOfDifferentSizesAreAUsageError) {
  const TempDir dir;
  std::mt19937_64 rng(5);
  std::vector<fs::path> files = write_runs(dir.path(), "a", 2, 16, rng);
  const std::vector<fs::path> other = write_runs(dir.path(), "b", 1, 20, rng);
  files.push_back(other.front());
  try {
    stats_of_images(files);
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("b0.exr: image is 20x20, the other runs 16x16"),
              std::string::npos)
        << e.what();
  }
}

// A golden's mean and variance of two sizes: both sizes said, not "the variance" blamed for a
// mean that may be the one changed.
TEST(NoisyImageFiles, AGoldensMeanAndVarianceOfTwoSizesNameBoth) {
  const TempDir dir;
  std::mt19937_64 rng(6);
  write_rgb_image(noisy(16, rng), dir.path() / "m.exr");
  write_rgb_image(noisy(20, rng), dir.path() / "v.exr");
  try {
    read_stats_images(dir.path() / "m.exr", dir.path() / "v.exr", 4, {});
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("m.exr is 16x16 and "), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("v.exr is 20x20"), std::string::npos) << e.what();
  }
}

// The fourth sweep: a variance of one channel (read as one variance for all three colours) or of
// 8-bit whole numbers (small variances rounded to 0) judged against noise never measured.
TEST(NoisyImageFiles, AVarianceNotAsBlessWritesItIsRefused) {
  const TempDir dir;
  std::mt19937_64 rng(7);
  write_rgb_image(noisy(16, rng), dir.path() / "m.exr");
  write_rgb_image(noisy(16, rng), dir.path() / "v8.png");  // 8-bit, as every PNG it writes
  const std::vector<float> grey(16 * 16, 0.01f);
  OIIO::ImageBuf one(OIIO::ImageSpec(16, 16, 1, OIIO::TypeDesc::FLOAT));
  one.set_pixels(one.roi(), OIIO::TypeDesc::FLOAT, grey.data());
  ASSERT_TRUE(one.write((dir.path() / "v1.exr").string()));
  const auto refusal = [&](const char* variance) -> std::string {
    try {
      read_stats_images(dir.path() / "m.exr", dir.path() / variance, 4, {{8, 1.0}});
      return "accepted";
    } catch (const UsageError& e) {
      return e.what();
    }
  };
  EXPECT_NE(refusal("v8.png").find("v8.png stores 8-bit whole numbers: a variance is kept in "
                                   "floating point"),
            std::string::npos)
      << refusal("v8.png");
  EXPECT_NE(refusal("v1.exr").find("v1.exr has 1 channel: a variance has one per colour"),
            std::string::npos)
      << refusal("v1.exr");
  write_rgb_image(noisy(16, rng), dir.path() / "v.exr");
  EXPECT_EQ(refusal("v.exr"), "accepted");
}

// 9 runs a side of 128x128 float EXR images (what a compare with a warm-up and 8 rounds has), from
// the files: the statistical check (reading 18 images, statistics, 3 scales x tiles x channels)
// against the per-pixel check of one pair. Both verdicts are asserted; the times are printed.
TEST(NoisyImageFiles, CostAgainstThePerPixelCheck) {
  const TempDir dir;
  std::mt19937_64 rng(7);
  const std::vector<fs::path> a = write_runs(dir.path(), "a", 9, 128, rng);
  const std::vector<fs::path> b = write_runs(dir.path(), "b", 9, 128, rng);
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const NoisyComparison noisy_result = compare_noisy(stats_of_images(a), stats_of_images(b), {});
  const auto t1 = Clock::now();
  const ImageMetrics per_pixel = compare_images(a.front(), b.front(), {});
  const auto t2 = Clock::now();
  EXPECT_EQ(noisy_result.verdict, NoisyVerdict::pass) << summarize(noisy_result);
  EXPECT_EQ(judge(per_pixel, {}), ImageVerdict::fail);  // why the per-pixel rule cannot be used
  const double noisy_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
  const double pixel_ms = std::chrono::duration<double, std::milli>(t2 - t1).count();
  std::printf(
      "128x128, 9 vs 9 runs: statistical check %.1f ms, per-pixel check of one pair %.1f ms\n",
      noisy_ms, pixel_ms);
}

}  // namespace
}  // namespace raygate

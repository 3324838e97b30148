// Image metrics through OpenImageIO on images made here with known differences.
#include "compare/image_compare.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "compare/golden.h"
#include "compare/noisy_image_files.h"
#include "core/error.h"
#include "core/fs.h"

namespace raygate {
namespace {

namespace OIIO = OIIO_NAMESPACE;

// A 10x10 RGB float image, uniform grey 0.5, with optional changed pixels.
std::filesystem::path make_image(const TempDir& dir, const std::string& name,
                                 std::vector<std::array<float, 5>> changes = {}, int size = 10) {
  OIIO::ImageBuf buf(OIIO::ImageSpec(size, size, 3, OIIO::TypeDesc::FLOAT));
  const float grey[3] = {0.5f, 0.5f, 0.5f};
  OIIO::ImageBufAlgo::fill(buf, grey);
  for (const auto& c : changes) {  // x, y, r, g, b
    const float v[3] = {c[2], c[3], c[4]};
    buf.setpixel(static_cast<int>(c[0]), static_cast<int>(c[1]), v);
  }
  const auto path = dir.path() / name;
  EXPECT_TRUE(buf.write(path.string()));
  return path;
}

TEST(ImageCompare, IdenticalImages) {
  TempDir dir;
  const ImageMetrics m = compare_images(make_image(dir, "a.exr"), make_image(dir, "b.exr"), {});
  EXPECT_TRUE(m.identical());
  EXPECT_EQ(judge(m, {}), ImageVerdict::pass);
  EXPECT_EQ(summarize(m), "identical");
}

TEST(ImageCompare, LocatesTheWorstPixelAndCountsFailures) {
  TempDir dir;
  const auto a = make_image(dir, "a.exr", {{3, 7, 0.5f, 0.9f, 0.5f}, {1, 1, 0.51f, 0.5f, 0.5f}});
  const auto b = make_image(dir, "b.exr");
  const ImageMetrics m = compare_images(a, b, {});
  EXPECT_NEAR(m.max_error, 0.4, 1e-6);
  EXPECT_EQ(m.max_x, 3);
  EXPECT_EQ(m.max_y, 7);
  EXPECT_EQ(m.max_channel, 1);
  EXPECT_NEAR(m.max_actual_value, 0.9, 1e-6);
  EXPECT_NEAR(m.max_expected_value, 0.5, 1e-6);
  EXPECT_EQ(m.pixels_over_fail, 2);
  EXPECT_DOUBLE_EQ(m.percent_over_fail, 2.0);
  EXPECT_EQ(judge(m, {}), ImageVerdict::fail);  // 2% > 0.02%
  ImageThresholds lenient;
  lenient.fail_percent = 5.0;
  EXPECT_EQ(judge(m, lenient), ImageVerdict::warn);
  lenient.hard_fail = 0.3;
  EXPECT_EQ(judge(m, lenient), ImageVerdict::fail);
  EXPECT_GT(m.luminance_bias(), 0.0);
}

TEST(ImageCompare, SizeMismatchAndNonFiniteValuesFail) {
  TempDir dir;
  const ImageMetrics sized =
      compare_images(make_image(dir, "a.exr", {}, 8), make_image(dir, "b.exr"), {});
  EXPECT_TRUE(sized.size_mismatch);
  EXPECT_EQ(judge(sized, {}), ImageVerdict::fail);
  EXPECT_EQ(summarize(sized), "size 8x8 but expected 10x10");
  const ImageMetrics nan = compare_images(make_image(dir, "n.exr", {{0, 0, NAN, 0.5f, 0.5f}}),
                                          make_image(dir, "b.exr"), {});
  EXPECT_EQ(nan.nonfinite_values, 1);
  EXPECT_EQ(nan.nonfinite_pixels, 1);
  EXPECT_EQ(judge(nan, {}), ImageVerdict::fail);
  EXPECT_EQ(summarize(nan), "1 NaN/Inf pixels of 100, first at (0,0)");
}

// Pixels, not channels: a pixel NaN in every channel is one, as is a pixel with an Inf.
TEST(ImageCompare, CountsNonFinitePixelsNotChannels) {
  TempDir dir;
  const ImageMetrics m = compare_images(
      make_image(dir, "n.exr", {{4, 2, NAN, NAN, NAN}, {6, 3, 0.5f, INFINITY, 0.5f}}),
      make_image(dir, "b.exr"), {});
  EXPECT_EQ(m.nonfinite_values, 4);
  EXPECT_EQ(m.nonfinite_pixels, 2);
  EXPECT_EQ(m.nonfinite_x, 4);
  EXPECT_EQ(m.nonfinite_y, 2);
  EXPECT_EQ(m.expected_nonfinite_pixels, 0);
  EXPECT_FALSE(m.identical());
  const ImageMetrics reversed = compare_images(make_image(dir, "b.exr"), dir.path() / "n.exr", {});
  EXPECT_EQ(reversed.nonfinite_pixels, 0);
  EXPECT_EQ(reversed.expected_nonfinite_pixels, 2);
}

TEST(ImageCompare, ReadsOtherFormatsAndRejectsUnreadableFiles) {
  TempDir dir;
  const auto png = make_image(dir, "a.png");
  const auto ppm = make_image(dir, "a.ppm");
  EXPECT_TRUE(compare_images(png, ppm, {}).identical());
  write_file_atomically(dir.path() / "junk.png", "not an image");
  EXPECT_THROW(compare_images(dir.path() / "junk.png", png, {}), UsageError);
  EXPECT_EQ(unreadable_image(png), "");
  const std::string why = unreadable_image(dir.path() / "junk.png");
  EXPECT_NE(why.find("junk.png: cannot read image: "), std::string::npos) << why;
  EXPECT_EQ(why.find('\n'), std::string::npos) << why;
}

// A header declaring 20000x20000 is refused before its pixels are decoded (a sweep's 1 MB PNG
// took 67 s and gigabytes); here the pixels are not even there.
TEST(ImageCompare, AnImageDeclaringHundredsOfMillionsOfPixelsIsRefusedByItsHeader) {
  TempDir dir;
  write_file_atomically(dir.path() / "huge.ppm", "P6\n20000 20000\n255\n\x01\x02\x03");
  const std::string why = unreadable_image(dir.path() / "huge.ppm");
  EXPECT_NE(why.find("huge.ppm: declares 20000x20000 pixels, more than raygate decodes"),
            std::string::npos)
      << why;
  // Every reader of pixels: bless from a run (a sweep's 8 KB PNG of 60000x60000 asked for 43 GB
  // first), Monte Carlo statistics, and the comparison itself.
  for (const auto& read : std::vector<std::function<void()>>{
           [&] { read_rgb_image(dir.path() / "huge.ppm"); },
           [&] { compare_images(dir.path() / "huge.ppm", dir.path() / "huge.ppm", {}); }}) {
    try {
      read();
      ADD_FAILURE() << "decoded";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("more than raygate decodes"), std::string::npos);
    }
  }
}

TEST(ImageCompare, EvidenceImagesAreWritten) {
  TempDir dir;
  const auto a = make_image(dir, "a.exr", {{2, 2, 0.6f, 0.5f, 0.5f}});
  const auto b = make_image(dir, "b.exr");
  write_evidence(a, b, dir.path() / "evidence", "balls");
  OIIO::ImageBuf diff((dir.path() / "evidence" / "balls.diff.png").string());
  ASSERT_TRUE(diff.read());
  float v[3];
  diff.getpixel(2, 2, v, 3);
  EXPECT_NEAR(v[0], 1.0, 1.0 / 255);  // |0.1| x 16 clamps to 1
  diff.getpixel(0, 0, v, 3);
  EXPECT_EQ(v[0], 0.0f);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "evidence" / "balls.actual.png"));
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "evidence" / "balls.expected.png"));
}

TEST(GoldenManifest, RoundTripsAndRejectsOtherSchemas) {
  TempDir dir;
  GoldenManifest m;
  m.suite = "ci";
  m.baseline_version = "raygate-baseline 0.1.0 source-sha256:abc";
  m.baseline_source_sha256 = "abc";
  m.upsert({"tetra", "tetra", 3, 96, 96, "center", "none", "tetra.png", std::string(64, 'f')});
  m.upsert({"balls", "balls", 2, 96, 96, "center", "none", "balls.png", std::string(64, 'e')});
  m.upsert({"tetra", "tetra", 3, 96, 96, "center", "none", "tetra.png", std::string(64, '0')});
  save_golden_manifest(m, dir.path());
  const GoldenManifest loaded = load_golden_manifest(dir.path());
  ASSERT_EQ(loaded.entries.size(), 2u);
  EXPECT_EQ(loaded.entries[0].id, "balls");  // sorted
  EXPECT_EQ(loaded.find("tetra")->sha256, std::string(64, '0'));
  EXPECT_EQ(loaded.baseline_source_sha256, "abc");
  // A hash not as bless writes it (short, uppercase) is a hand-edited manifest: exit 2, its
  // path; not "the golden was changed after it was blessed".
  for (const std::string& bad : {std::string("abc"), std::string(64, 'F'), std::string(64, 'g')}) {
    m.upsert({"tetra", "tetra", 3, 96, 96, "center", "none", "tetra.png", bad});
    save_golden_manifest(m, dir.path());
    try {
      load_golden_manifest(dir.path());
      ADD_FAILURE() << bad << " was accepted";
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("64 lowercase hex digits"), std::string::npos)
          << e.what();
    }
  }
  write_file_atomically(dir.path() / "manifest.json", R"({"schema_version": 99})");
  EXPECT_THROW(load_golden_manifest(dir.path()), UsageError);
  EXPECT_TRUE(load_golden_manifest(dir.path() / "empty").entries.empty());
}

// A manifest that is a symlink loop is the user's folder to fix (exit 2, the path), not the
// file system's raw error (the sweep of 2026-11-29: exit 3, "filesystem error: status: ...").
TEST(GoldenManifest, ASymlinkLoopIsAUsageErrorNamingIt) {
  TempDir dir;
  std::filesystem::create_symlink(dir.path() / "manifest.json", dir.path() / "manifest.json");
  try {
    load_golden_manifest(dir.path());
    ADD_FAILURE() << "a symlink loop was read";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("manifest.json: cannot be read: "), std::string::npos)
        << e.what();
  }
}

// A crafted manifest must not make verify read, or bless overwrite, a file outside its folder.
TEST(GoldenManifest, RefusesFileNamesThatLeaveTheGoldenFolder) {
  TempDir dir;
  GoldenManifest m;
  m.suite = "ci";
  m.upsert({"balls", "balls", 2, 96, 96, "center", "none", "../../etc/passwd", "ee"});
  save_golden_manifest(m, dir.path());
  try {
    load_golden_manifest(dir.path());
    FAIL() << "a manifest with a '../' file name was accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("$.images[0].file"), std::string::npos) << e.what();
  }
  m.entries = {{"../x", "balls", 2, 96, 96, "center", "none", "balls.png", "ee"}};
  save_golden_manifest(m, dir.path());
  EXPECT_THROW(load_golden_manifest(dir.path()), UsageError);
}

}  // namespace
}  // namespace raygate

// `raygate golden`: the shipped goldens match the baseline bit for bit; a changed or missing
// golden is caught with the right exit code, and bless writes only what it is asked to.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "cli_support.h"
#include "compare/golden.h"
#include "compare/image_compare.h"
#include "core/sha256.h"

namespace raygate::test {
namespace {

namespace OIIO = OIIO_NAMESPACE;
const std::filesystem::path kGolden = std::filesystem::path(RAYGATE_SOURCE_DIR) / "golden";

// Every shipped golden is re-rendered: any change to the baseline or the generators that moves
// a single pixel fails here (re-bless on purpose with `raygate golden bless`).
TEST(GoldenCli, ShippedGoldensAreBitExact) {
  TempDir dir;
  const CliRun r = run_raygate({"golden", "verify", "--work-dir", "work"}, dir);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_NE(r.out.find("13 scenes: 13 identical, 0 different, 0 missing"), std::string::npos)
      << r.out;
}

TEST(GoldenCli, ManifestDescribesEveryImage) {
  const GoldenManifest m = load_golden_manifest(kGolden);
  EXPECT_EQ(m.suite, "ci");
  EXPECT_EQ(m.entries.size(), 13u);
  EXPECT_EQ(m.baseline_source_sha256.size(), 64u);
  for (const GoldenEntry& e : m.entries) {
    EXPECT_EQ(sha256_file_hex(kGolden / e.file), e.sha256) << e.id;
  }
}

TEST(GoldenCli, ChangedGoldenFailsWithEvidence) {
  TempDir dir;
  std::filesystem::copy(kGolden, dir.path() / "golden");
  OIIO::ImageBuf buf((dir.path() / "golden" / "tetra.png").string());
  ASSERT_TRUE(buf.read(0, 0, true, OIIO::TypeDesc::FLOAT));
  const float white[3] = {1, 1, 1};
  buf.setpixel(10, 10, white);
  ASSERT_TRUE(buf.write((dir.path() / "golden" / "tetra.png").string(), OIIO::TypeDesc::UINT8));
  const CliRun r = run_raygate(
      {"golden", "verify", "tetra", "--golden-dir", "golden", "--work-dir", "work"}, dir);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_NE(r.out.find("DIFFERENT tetra"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("at (10,10)"), std::string::npos) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "work/evidence/tetra.diff.png"));
}

TEST(GoldenCli, MissingGoldenIsAnErrorNotAPass) {
  TempDir dir;
  std::filesystem::copy(kGolden, dir.path() / "golden");
  std::filesystem::remove(dir.path() / "golden" / "sample.png");
  const CliRun r = run_raygate(
      {"golden", "verify", "sample", "tetra", "--golden-dir", "golden", "--work-dir", "work"}, dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("MISSING   sample"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("raygate golden bless sample"), std::string::npos) << r.out;
}

TEST(GoldenCli, BlessWritesOnlyTheNamedScenes) {
  TempDir dir;
  const CliRun r = run_raygate(
      {"golden", "bless", "tetra", "--golden-dir", "fresh", "--work-dir", "work"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const GoldenManifest m = load_golden_manifest(dir.path() / "fresh");
  ASSERT_EQ(m.entries.size(), 1u);
  EXPECT_EQ(m.entries[0].id, "tetra");
  // The freshly blessed image is the shipped one, pixel for pixel (deterministic baseline; the
  // bytes may differ: goldens blessed by an older baseline's PNG writer decode to the same pixels).
  EXPECT_EQ(m.entries[0].sha256, sha256_file_hex(dir.path() / "fresh" / "tetra.png"));
  EXPECT_TRUE(compare_images(dir.path() / "fresh" / "tetra.png", kGolden / "tetra.png", {})
                  .identical());
  const CliRun unknown = run_raygate({"golden", "bless", "nope", "--golden-dir", "fresh"}, dir);
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.out.find("suite 'ci' has no scene 'nope'"), std::string::npos);
}

}  // namespace
}  // namespace raygate::test

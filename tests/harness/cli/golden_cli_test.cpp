// `raygate golden`: the shipped goldens (golden/raygate-baseline/) match the baseline bit for
// bit; a changed or missing golden is caught with the right exit code, and bless writes only
// what it is asked to. And a new tracer's first use: with no goldens of its own it is judged on
// images head against base only, says so once, then blesses its own from a run and is gated
// on them; its garbage image fails the change (exit 1), and a document of no scenes never passes.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <nlohmann/json.hpp>

#include "cli_support.h"
#include "compare/golden.h"
#include "compare/image_compare.h"
#include "core/sha256.h"
#include "results/results.h"
#include "tracer_fixture.h"

namespace raygate::test {
namespace {

namespace OIIO = OIIO_NAMESPACE;

std::size_t occurrences(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) {
    ++n;
  }
  return n;
}
const std::filesystem::path kGolden =
    std::filesystem::path(RAYGATE_SOURCE_DIR) / "golden" / "raygate-baseline";

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
  // Blessed that way (its manifest hash follows it): a golden the baseline no longer renders.
  // Without this the golden is refused as changed after its blessing (exit 3, golden tests).
  const std::filesystem::path manifest = dir.path() / "golden" / "manifest.json";
  std::string text = read_file(manifest);
  const std::string old_hash = sha256_file_hex(kGolden / "tetra.png");
  ASSERT_NE(text.find(old_hash), std::string::npos);
  text.replace(text.find(old_hash), old_hash.size(),
               sha256_file_hex(dir.path() / "golden" / "tetra.png"));
  write_file_atomically(manifest, text);
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
  // The hint names the folder given: `raygate golden bless sample` alone would bless the shipped
  // goldens (the sweep of 2026-11-29).
  EXPECT_NE(r.out.find("raygate golden bless --suite "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" --golden-dir golden sample"), std::string::npos) << r.out;
}

// A golden whose bytes match the manifest but are no image (tampered, manifest hash updated):
// that scene is an ERROR, the others are still verified, exit 3, as verify --from-run has it.
TEST(GoldenCli, AnUnreadableGoldenIsAnErrorOfItsSceneOnly) {
  TempDir dir;
  std::filesystem::copy(kGolden, dir.path() / "golden");
  const std::filesystem::path manifest = dir.path() / "golden" / "manifest.json";
  write_file_atomically(dir.path() / "golden" / "tetra.png", "not a picture at all");
  std::string text = read_file(manifest);
  const std::string old_hash = sha256_file_hex(kGolden / "tetra.png");
  text.replace(text.find(old_hash), old_hash.size(),
               sha256_file_hex(dir.path() / "golden" / "tetra.png"));
  write_file_atomically(manifest, text);
  const CliRun r = run_raygate(
      {"golden", "verify", "tetra", "sample", "--golden-dir", "golden", "--work-dir", "work"}, dir);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  for (const char* line :
       {"ERROR     tetra        golden/tetra.png: cannot read image", "ok        sample"}) {
    EXPECT_NE(r.out.find(line), std::string::npos) << r.out;
  }
}

// The fifth sweep: a golden of another size than its manifest lists, its hash updated, was
// judged DIFFERENT (exit 1, "your change regressed"); the manifest does not describe its image,
// so the golden cannot judge (exit 3).
TEST(GoldenCli, AGoldenOfAnotherSizeThanItsManifestCannotJudge) {
  TempDir dir;
  std::filesystem::copy(kGolden, dir.path() / "golden");
  const std::filesystem::path tetra = dir.path() / "golden" / "tetra.png";
  const OIIO::ImageBuf small =
      OIIO::ImageBufAlgo::resize(OIIO::ImageBuf(tetra.string()), "", 0, OIIO::ROI(0, 16, 0, 16));
  ASSERT_TRUE(small.write(tetra.string(), OIIO::TypeDesc::UINT8));
  const std::filesystem::path manifest = dir.path() / "golden" / "manifest.json";
  std::string text = read_file(manifest);
  const std::string old_hash = sha256_file_hex(kGolden / "tetra.png");
  text.replace(text.find(old_hash), old_hash.size(), sha256_file_hex(tetra));
  write_file_atomically(manifest, text);
  const CliRun r = run_raygate(
      {"golden", "verify", "tetra", "--golden-dir", "golden", "--work-dir", "work"}, dir);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_NE(r.out.find("ERROR     tetra        tetra.png is 16x16, but the manifest lists it at"),
            std::string::npos)
      << r.out;
}

// Images without their manifest are not goldens nobody has: the words say the manifest is
// missing, and do not invite a bless over pictures no one has looked at.
TEST(GoldenCli, AMissingManifestIsSaidSo) {
  TempDir dir;
  std::filesystem::copy(kGolden, dir.path() / "golden");
  std::filesystem::remove(dir.path() / "golden" / "manifest.json");
  const CliRun r = run_raygate(
      {"golden", "verify", "tetra", "--golden-dir", "golden", "--work-dir", "work"}, dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("MISSING   tetra        golden/tetra.png is there, but "
                       "golden/manifest.json is missing"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("raygate golden bless"), std::string::npos) << r.out;
}

TEST(GoldenCli, AGoldenDirThatIsAFileIsAUsageError) {
  TempDir dir;
  write_file_atomically(dir.path() / "file", "x");
  const CliRun r =
      run_raygate({"golden", "bless", "tetra", "--golden-dir", "file", "--work-dir", "work"}, dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  // bless refuses it as the command line is read, before rendering; verify as it reads it.
  EXPECT_NE(r.out.find("--golden-dir: cannot write"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("filesystem error"), std::string::npos) << r.out;
  const CliRun verify =
      run_raygate({"golden", "verify", "tetra", "--golden-dir", "file", "--work-dir", "work"}, dir);
  EXPECT_EQ(verify.exit_code, 2) << verify.out;
  EXPECT_NE(verify.out.find("file is a file, not a folder"), std::string::npos) << verify.out;
}

TEST(GoldenCli, BlessWritesOnlyTheNamedScenes) {
  TempDir dir;
  const CliRun r =
      run_raygate({"golden", "bless", "tetra", "--golden-dir", "fresh", "--work-dir", "work"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const GoldenManifest m = load_golden_manifest(dir.path() / "fresh");
  ASSERT_EQ(m.entries.size(), 1u);
  EXPECT_EQ(m.entries[0].id, "tetra");
  // The freshly blessed image is the shipped one, pixel for pixel (deterministic baseline; the
  // bytes may differ: goldens blessed by an older baseline's PNG writer decode to the same pixels).
  EXPECT_EQ(m.entries[0].sha256, sha256_file_hex(dir.path() / "fresh" / "tetra.png"));
  EXPECT_TRUE(
      compare_images(dir.path() / "fresh" / "tetra.png", kGolden / "tetra.png", {}).identical());
  const CliRun unknown = run_raygate({"golden", "bless", "nope", "--golden-dir", "fresh"}, dir);
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.out.find("suite 'ci' has no scene 'nope'"), std::string::npos);
}

// Re-blessing the baseline's goldens keeps whom they are shared with (the bbox control).
TEST(GoldenCli, BlessKeepsTheSharedWithList) {
  TempDir dir;
  std::filesystem::copy(kGolden, dir.path() / "golden");
  const CliRun r = run_raygate(
      {"golden", "bless", "tetra", "--golden-dir", "golden", "--work-dir", "work"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const GoldenManifest m = load_golden_manifest(dir.path() / "golden");
  EXPECT_EQ(m.shared_with, std::vector<std::string>{"raygate-baseline-bbox"});
  EXPECT_EQ(m.entries.size(), 13u);
}

// Sweep 17: verify against a folder that does not exist printed 13 "MISSING ... create it with
// bless" lines; a mistyped folder is said once.
TEST(GoldenCli, VerifyingAFolderThatDoesNotExistSaysSoOnce) {
  TempDir dir;
  const CliRun r = run_raygate({"golden", "verify", "--golden-dir", "typo"}, dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_EQ(r.out.rfind("raygate: error: --golden-dir typo does not exist: no goldens to "
                        "verify",
                        0),
            0u)
      << r.out;
  EXPECT_EQ(r.out.find("MISSING"), std::string::npos) << r.out;
}

// A sweep: a bless killed after 5 of 13 scenes left those 5 new and 8 old, all labelled with the
// new baseline. The renders come first and the set is swapped once: a bless that fails on its
// second scene (as a kill there would end it) leaves the old set, manifest and images, whole.
TEST(GoldenCli, ABlessThatFailsHalfwayLeavesTheOldSetWhole) {
  TempDir dir;
  std::filesystem::copy(kGolden, dir.path() / "golden");
  const std::string manifest = read_file(dir.path() / "golden" / "manifest.json");
  const std::string real =
      (std::filesystem::path(RAYGATE_EXE).parent_path() / "raygate-baseline").string();
  const std::string mark = (dir.path() / "rendered").string();
  write_file_atomically(dir.path() / "second-fails",
                        "#!/bin/sh\ncase \"$*\" in *.nff*)\n  if [ -e '" + mark +
                            "' ]; then exit 7; fi\n  : > '" + mark + "';;\nesac\nexec '" + real +
                            "' \"$@\"\n");
  std::filesystem::permissions(dir.path() / "second-fails", std::filesystem::perms::owner_all);
  std::filesystem::remove(dir.path() / "golden" / "tetra.png");  // the first scene's, to tell
  const CliRun r = run_raygate({"golden", "bless", "tetra", "balls", "--golden-dir", "golden",
                                "--work-dir", "work", "--baseline", "./second-fails"},
                               dir);
  EXPECT_EQ(r.exit_code, 3) << r.out;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "rendered")) << r.out;
  EXPECT_EQ(read_file(dir.path() / "golden" / "manifest.json"), manifest);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "golden" / "tetra.png"));  // not blessed
}

// The ci suite's balls, at the settings of the baseline's golden: the fixture tracer has no
// reflections, so the baseline's picture would fail it.
inline constexpr const char* kCiBallsSuite = R"({
  "name": "ci-balls",
  "description": "the ci suite's balls, as its golden was made",
  "sampling": "center",
  "scenes": [{"id": "balls", "scene": "balls", "size": 4, "resolution": [128, 128]}]
})";

class NewTracerCli : public TracerRepoTest {
 protected:
  NewTracerCli() : TracerRepoTest(kCiBallsSuite) {}

  std::vector<std::string> measure(std::vector<std::string> args) const {
    args.insert(args.end(), {"--repo", repo_.path().string(), "--adapter", "make-nff", "--suite",
                             suite_.string(), "--cache-dir", cache_.string(), "--no-store",
                             "--warmup", "0", "--max-rounds", "2"});
    return args;
  }
};

// First use: no --golden-dir, and make-nff has no golden/make-nff/. The A/A compare is judged on
// head against base only and passes; the missing goldens are one note, not one per scene. Then
// the first-use path: bless from the run, and the next run is gated on the tracer's own goldens.
TEST_F(NewTracerCli, FirstCompareWithoutGoldensPassesAndSaysSoOnce) {
  const std::string sha = commit(sources_.fast, "tracer");
  const std::filesystem::path out = dir_.path() / "c.json";
  const CliRun r =
      run_raygate(measure({"compare", "--base", sha, "--head", sha, "--out", out.string()}), dir_);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  const std::filesystem::path own = kSource / "golden" / "make-nff";
  EXPECT_EQ(occurrences(r.out, "no goldens: " + own.string() + " does not exist"), 1u) << r.out;
  EXPECT_TRUE(has(r.out, "note: images not checked against goldens")) << r.out;
  EXPECT_TRUE(has(r.out, "raygate golden bless --from-run RESULTS.json --role head")) << r.out;
  const ResultsDocument d = read_results(out);
  EXPECT_EQ(d.settings.goldens, "none");
  EXPECT_EQ(d.settings.golden_dir, own.string());
  ASSERT_EQ(d.scenes.size(), 1u);
  bool head_vs_base = false;
  for (const ImageCheck& check : d.scenes[0].images) {
    if (check.reference == ImageReference::base) head_vs_base = check.verdict == ImageVerdict::pass;
    if (check.reference == ImageReference::golden) {
      EXPECT_EQ(check.verdict, ImageVerdict::missing);
    }
  }
  EXPECT_TRUE(head_vs_base);

  const CliRun bless = run_raygate(
      {"golden", "bless", "--from-run", out.string(), "--role", "head", "--golden-dir", "mine"},
      dir_);
  ASSERT_EQ(bless.exit_code, 0) << bless.out;
  const CliRun gated =
      run_raygate(measure({"run", "--rev", sha, "--golden-dir", "mine", "--out", "r.json"}), dir_);
  EXPECT_EQ(gated.exit_code, 0) << gated.out;
  EXPECT_FALSE(has(gated.out, "no goldens")) << gated.out;
  const ResultsDocument run = read_results(dir_.path() / "r.json");
  EXPECT_EQ(run.settings.goldens, "make-nff");
  EXPECT_EQ(run.scenes.at(0).images.at(0).verdict, ImageVerdict::pass)
      << run.scenes.at(0).images.at(0).error;

  // The same document with its scenes taken away is no pass.
  nlohmann::json empty = nlohmann::json::parse(read_file(out));
  empty["scenes"] = nlohmann::json::array();
  write_file_atomically(dir_.path() / "empty.json", empty.dump());
  const CliRun gate = run_raygate({"gate", "empty.json"}, dir_);
  EXPECT_EQ(gate.exit_code, 3) << gate.out;
  EXPECT_TRUE(has(gate.out,
                  "gate: COULD NOT MEASURE: 0 scenes, 0 failed, 0 warnings; the "
                  "document holds no scenes: nothing was measured"))
      << gate.out;
}

// A head that exits 0 but writes text where its image belongs has failed on that scene: exit 1
// (base measured), not 3, and the reason is one line.
TEST_F(NewTracerCli, GarbageImageOfHeadFailsTheChange) {
  const std::string base = commit(sources_.fast, "tracer");
  const std::string head = commit(sources_.garbling, "write text, not an image");
  const CliRun r =
      run_raygate(measure({"compare", "--base", base, "--head", head, "--out", "c.json"}), dir_);
  EXPECT_EQ(r.exit_code, 1) << r.out;
  EXPECT_TRUE(has(r.out, "image head vs base: ")) << r.out;
  EXPECT_TRUE(has(r.out, "cannot read image")) << r.out;
  // Named: a range-for over read_results(...).scenes.at(0) would outlive the document (C++20),
  // and read freed strings (this test once failed on garbage where the path began).
  const ResultsDocument d = read_results(dir_.path() / "c.json");
  for (const ImageCheck& check : d.scenes.at(0).images) {
    if (check.role != Role::head) continue;
    EXPECT_EQ(check.verdict, ImageVerdict::fail) << to_string(check.reference);
    EXPECT_EQ(check.error.find('\n'), std::string::npos) << check.error;
  }
}

}  // namespace
}  // namespace raygate::test

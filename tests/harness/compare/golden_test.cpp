// compare/golden: a golden manifest is untrusted input. Every field is read with its JSON path:
// a wrong type, an unknown key, a duplicate image id or inflation scale, a whole number that is
// a fraction, too large for its type (1e12, 1e20, 2^32 + 2) or out of range is refused with the
// path and the value, never converted (a wrapped run count judged goldens at 2 runs; a float
// past int's range was undefined behaviour). A noise.runs out of range on either side is the
// golden's problem (a check error), not a malformed file.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <string>

#include "compare/golden.h"
#include "core/error.h"
#include "core/fs.h"

namespace raygate {
namespace {

using nlohmann::json;

// A Monte Carlo golden of two scenes, as bless writes it.
GoldenManifest two_scene_manifest() {
  GoldenManifest manifest;
  manifest.suite = "ci";
  manifest.entries.push_back(
      {"balls", "balls", 1, 48, 48, "center", "", "balls.mean.exr", std::string(64, 'a')});
  manifest.entries.push_back(
      {"tetra", "tetra", 3, 32, 32, "center", "", "tetra.mean.exr", std::string(64, 'c')});
  manifest.noise["balls"] = {
      8, "balls.variance.exr", std::string(64, 'e'), {{8, 1.02}, {kWholeImage, 1.5}}};
  manifest.noise["tetra"] = {9, "tetra.variance.exr", std::string(64, '1'), {{8, 1.0}}};
  return manifest;
}

// The message of loading the manifest of `golden_dir`; "" when it loads.
std::string load_error(const std::filesystem::path& golden_dir) {
  try {
    load_golden_manifest(golden_dir);
    return "";
  } catch (const UsageError& e) {
    return e.what();
  }
}

class GoldenManifestTest : public ::testing::Test {
 protected:
  GoldenManifestTest() {
    save_golden_manifest(two_scene_manifest(), dir_.path());
    doc_ = json::parse(read_file(manifest_file()));
  }

  std::filesystem::path manifest_file() const { return dir_.path() / "manifest.json"; }

  // The message of loading `doc`; "" when it loads.
  std::string load_error(const json& doc) const {
    write_file_atomically(manifest_file(), doc.dump(2));
    return raygate::load_error(dir_.path());
  }

  void expect_refused(const json& doc, const std::string& message) const {
    const std::string error = load_error(doc);
    EXPECT_NE(error.find(manifest_file().string() + ": " + message), std::string::npos)
        << "expected: " << message << "\ngot: " << error;
    EXPECT_EQ(error.find("json.exception"), std::string::npos) << error;
  }

  TempDir dir_;
  json doc_;
};

TEST_F(GoldenManifestTest, WhatBlessWritesReadsBack) {
  const GoldenManifest back = load_golden_manifest(dir_.path());
  EXPECT_EQ(back.noise, two_scene_manifest().noise);
  ASSERT_EQ(back.entries.size(), 2u);
  EXPECT_EQ(back.entries[1].size, 3);
}

TEST_F(GoldenManifestTest, ADuplicateIdIsRefusedWhereItIs) {
  json doc = doc_;
  doc["images"].push_back(doc["images"][0]);
  expect_refused(doc, "$.images[2].id: duplicate id \"balls\"");
  doc = doc_;
  doc["images"][1]["id"] = "balls";  // the noise of one with the mean of the other
  expect_refused(doc, "$.images[1].id: duplicate id \"balls\"");
}

TEST_F(GoldenManifestTest, WholeNumbersAreNeverConverted) {
  const struct {
    const char* field;
    json value;
    std::string message;
  } cases[] = {
      {"width", json::parse("1e20"), "$.images[0].width: expected a whole number, found number"},
      {"width", "128", "$.images[0].width: expected a whole number, found string \"128\""},
      {"width", -5,
       "$.images[0].width: expected a whole number from 1 to 1048576, found number -5"},
      {"height", 0,
       "$.images[0].height: expected a whole number from 1 to 1048576, found number 0"},
      {"size", 4294967298LL, "$.images[0].size: expected a whole number from 0 to 1000000"},
      {"size", 2.5, "$.images[0].size: expected a whole number, found number 2.5"},
  };
  for (const auto& c : cases) {
    json doc = doc_;
    doc["images"][0][c.field] = c.value;
    expect_refused(doc, c.message);
  }
  json doc = doc_;
  doc["images"][0]["noise"]["runs"] = json::parse("1e12");
  expect_refused(doc, "$.images[0].noise.runs: expected a whole number, found number");
  doc["images"][0]["noise"]["runs"] = 2.5;
  expect_refused(doc, "$.images[0].noise.runs: expected a whole number, found number 2.5");
  for (const json& tile_px : {json(-8), json(4294967304LL), json::parse("1e15")}) {
    doc = doc_;
    doc["images"][0]["noise"]["inflation"][0]["tile_px"] = tile_px;
    expect_refused(doc, "$.images[0].noise.inflation[0].tile_px: expected a whole number");
  }
}

// docs/monte-carlo-images.md: a run count outside 2 to 10^6 is a golden that cannot judge, a
// check error (exit 3) on either side, 2^32 + 2 included (it once wrapped to 2).
TEST_F(GoldenManifestTest, RunsOutOfRangeOnEitherSideAreTheGoldensProblem) {
  for (const long long runs : {1LL, -3LL, 10'000'000LL, 4294967298LL}) {
    json doc = doc_;
    doc["images"][1]["noise"]["runs"] = runs;
    ASSERT_EQ(load_error(doc), "") << runs;
    const GoldenNoise noise = load_golden_manifest(dir_.path()).noise.at("tetra");
    EXPECT_EQ(noise.runs, runs);
    const std::optional<std::string> problem = golden_noise_problem(noise, "m: 'tetra'");
    ASSERT_TRUE(problem) << runs;
    EXPECT_EQ(*problem, "m: 'tetra': noise.runs " + std::to_string(runs) +
                            " is not a number of runs (2 to 1000000)");
  }
}

TEST_F(GoldenManifestTest, UnknownKeysAreRefusedAtEveryLevel) {
  json doc = doc_;
  // The fifth sweep: a word bless never writes was found only when the golden judged (exit 3).
  doc["images"][0]["accel"] = "warp";
  expect_refused(doc, "$.images[0].accel: unknown value \"warp\" (bless writes none, bbox)");
  doc = doc_;
  doc["images"][0]["sampling"] = "random";
  expect_refused(doc,
                 "$.images[0].sampling: unknown value \"random\" (bless writes center, corners)");
  doc = doc_;
  doc["extra"] = 1;
  expect_refused(doc, "$.extra: unknown key 'extra'");
  doc = doc_;
  doc["images"][0]["colour"] = "red";
  expect_refused(doc, "$.images[0].colour: unknown key 'colour'");
  doc = doc_;
  doc["images"][0]["noise"]["runz"] = 8;
  expect_refused(doc, "$.images[0].noise.runz: unknown key 'runz' (did you mean 'runs'?)");
  doc = doc_;
  doc["images"][0]["noise"]["inflation"][0]["scale"] = 8;
  expect_refused(doc, "$.images[0].noise.inflation[0].scale: unknown key 'scale'");
}

TEST_F(GoldenManifestTest, ASecondInflationForOneTileScaleIsRefused) {
  json doc = doc_;
  doc["images"][0]["noise"]["inflation"].push_back({{"tile_px", 8}, {"factor", 50.0}});
  expect_refused(doc, "$.images[0].noise.inflation[2].tile_px: a second entry for tile_px 8");
}

TEST_F(GoldenManifestTest, WrongTypesAndMissingKeysNameTheirPath) {
  json doc = doc_;
  doc["images"] = json::object();
  expect_refused(doc, "$.images: expected an array, found an object");
  doc = doc_;
  doc["images"][0]["sha256"] = 12345;
  expect_refused(doc, "$.images[0].sha256: expected a string, found number 12345");
  doc = doc_;
  doc["images"][0]["noise"]["inflation"] = "big";
  expect_refused(doc, "$.images[0].noise.inflation: expected an array, found string \"big\"");
  doc = doc_;
  doc["images"][0]["noise"].erase("variance_sha256");
  expect_refused(doc, "$.images[0].noise: missing required key 'variance_sha256'");
  doc = doc_;
  doc["schema_version"] = 2;
  expect_refused(doc, "$.schema_version: schema_version 2 is not supported (expected 1)");
}

TEST(GoldenManifest, AGoldenFolderThatIsAFileIsAUsageError) {
  const TempDir dir;
  write_file_atomically(dir.path() / "file", "x");
  EXPECT_EQ(load_error(dir.path() / "file"),
            (dir.path() / "file").string() +
                " is a file, not a folder: a golden folder holds manifest.json and the images it "
                "lists");
}

// The sweep of 2026-11-29: a folder was "changed after it was blessed" (the SHA-256 of nothing),
// and a symlink loop threw over every other scene of the verify.
TEST(GoldenFile, AFolderOrALoopIsNamedForWhatItIs) {
  const TempDir dir;
  std::filesystem::create_directories(dir.path() / "sub");
  std::filesystem::create_symlink("loop", dir.path() / "loop");
  const std::string sha(64, '0');
  const std::optional<std::string> folder = golden_file_problem(dir.path(), "sub", sha);
  ASSERT_TRUE(folder.has_value());
  EXPECT_NE(folder->find("is not a regular file"), std::string::npos) << *folder;
  const std::optional<std::string> loop = golden_file_problem(dir.path(), "loop", sha);
  ASSERT_TRUE(loop.has_value());
  EXPECT_NE(loop->find("cannot be read"), std::string::npos) << *loop;
  EXPECT_NE(loop->find("symbolic links"), std::string::npos) << *loop;
}

}  // namespace
}  // namespace raygate

// `raygate scenes`: listing, generating to a file or stdout, and clear errors with exit 2.
#include <gtest/gtest.h>

#include "cli_support.h"

namespace raygate::test {
namespace {

TEST(ScenesCli, ListsThirteenScenes) {
  TempDir dir;
  const CliRun r = run_raygate({"scenes", "list"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  for (const char* name : {"balls", "gears", "mount", "rings", "teapot", "tetra", "tree", "lattice",
                           "shells", "jacks", "sombrero", "sample", "nurbtst"}) {
    EXPECT_NE(r.out.find(std::string("\n") + name + " "), std::string::npos) << name;
  }
}

TEST(ScenesCli, GeneratesTheSpdBytes) {
  TempDir dir;
  const CliRun r = run_raygate({"scenes", "generate", "balls", "--size", "1", "-o", "b.nff"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string text = read_file(dir.path() / "b.nff");
  EXPECT_EQ(text.size(), 619u);  // spd-spec.md Table A
  EXPECT_EQ(text.substr(0, 20), "b 0.078 0.361 0.753\n");
  const CliRun stdout_run = run_raygate({"scenes", "generate", "balls", "--size", "1"}, dir);
  EXPECT_EQ(stdout_run.out, text);
}

TEST(ScenesCli, TessellateAndResolution) {
  TempDir dir;
  const CliRun r = run_raygate(
      {"scenes", "generate", "balls", "--size", "1", "-t", "2", "--resolution", "64x48"}, dir);
  ASSERT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("resolution 64 48\n"), std::string::npos);
  EXPECT_EQ(r.out.find("\ns "), std::string::npos);  // no spheres left
  std::size_t patches = 0;
  for (std::size_t at = r.out.find("pp 3"); at != std::string::npos;
       at = r.out.find("pp 3", at + 1)) {
    ++patches;
  }
  EXPECT_EQ(patches, 10u * 12 * 2 * 2);  // 10 spheres x 12 res^2
}

TEST(ScenesCli, BadInputIsExitTwoWithOneClearLine) {
  TempDir dir;
  CliRun r = run_raygate({"scenes", "generate", "balls", "--size", "0"}, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "raygate: error: scene 'balls': size 0 is out of range 1..6\n");
  r = run_raygate({"scenes", "generate", "ballz"}, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unknown scene 'ballz'"), std::string::npos);
  r = run_raygate({"scenes", "generate", "balls", "--resolution", "64by64"}, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("expected WIDTHxHEIGHT"), std::string::npos);
  r = run_raygate({"scenes", "frobnicate"}, dir);
  EXPECT_EQ(r.exit_code, 2);
}

}  // namespace
}  // namespace raygate::test

// `raygate scenes convert`: an NFF file to POV-Ray, OBJ + MTL or pbrt-v4, the files it wrote
// on standard output, and exit 2 with one clear line for a malformed scene or an unknown format.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.h"

namespace raygate::test {
namespace {

constexpr const char* kScene =
    "v\nfrom 0 -5 0\nat 0 0 0\nup 0 0 1\nangle 40\nhither 1\nresolution 32 32\n"
    "l 2 -4 3\nf 1 0.5 0 0.8 0.2 10 0 1\ns 0 0 0 1\nc 0 0 -1 0.5 0 0 1 0\n";

void write(const TempDir& dir, const char* name, const std::string& text) {
  write_file_atomically(dir.path() / name, text);
}

TEST(ScenesConvertCli, WritesEachFormat) {
  TempDir dir;
  write(dir, "in.nff", kScene);
  CliRun r = run_raygate({"scenes", "convert", "in.nff", "--to", "pov", "-o", "out/in.pov"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out, "out/in.pov\n");
  const std::string pov = read_file(dir.path() / "out" / "in.pov");
  EXPECT_EQ(pov.rfind("// POV-Ray 3.7 scene converted from in.nff", 0), 0u);
  EXPECT_NE(pov.find("\nsphere { <0, 0, 0>, 1 material { F1 } }\n"), std::string::npos);
  EXPECT_NE(pov.find(" open material { F1 } }\n"), std::string::npos);

  r = run_raygate({"scenes", "convert", "in.nff", "--to", "obj", "-o", "in.obj", "--segments", "8"},
                  dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out, "in.obj\nin.mtl\n");
  EXPECT_NE(read_file(dir.path() / "in.obj").find("\nmtllib in.mtl\no sphere1\nusemtl f1\n"),
            std::string::npos);
  EXPECT_NE(read_file(dir.path() / "in.mtl").find("newmtl f1\n"), std::string::npos);

  r = run_raygate({"scenes", "convert", "in.nff", "--to", "pbrt", "-o", "in.pbrt"}, dir);
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string pbrt = read_file(dir.path() / "in.pbrt");
  EXPECT_NE(pbrt.find("\nScale -1 1 1"), std::string::npos);
  EXPECT_NE(pbrt.find("Shape \"sphere\""), std::string::npos);
}

TEST(ScenesConvertCli, SameInputSameBytes) {
  TempDir dir;
  write(dir, "in.nff", kScene);
  for (const char* format : {"pov", "obj", "pbrt"}) {
    ASSERT_EQ(
        run_raygate({"scenes", "convert", "in.nff", "--to", format, "-o", "a.out"}, dir).exit_code,
        0);
    const std::string first = read_file(dir.path() / "a.out");
    ASSERT_EQ(
        run_raygate({"scenes", "convert", "in.nff", "--to", format, "-o", "a.out"}, dir).exit_code,
        0);
    EXPECT_EQ(read_file(dir.path() / "a.out"), first) << format;
  }
}

TEST(ScenesConvertCli, MalformedSceneIsExitTwoWithItsLocation) {
  TempDir dir;
  write(dir, "bad.nff",
        "v\nfrom 0 0 0\nat 0 0 1\nup 0 1 0\nangle 45\nhither 1\nresolution 8 8\n"
        "f 1 1 1 1 0 0 0\ns 0 0 0 1\n");
  const CliRun r = run_raygate({"scenes", "convert", "bad.nff", "--to", "pov", "-o", "x.pov"}, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out.rfind("raygate: error: bad.nff:9:1: expected ", 0), 0u) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.pov"));
}

// A sweep: a sphere at 1e308 of radius 1e308 was tessellated into vertices of "inf", written
// with exit 0. A value that overflows once converted is refused and nothing is written.
TEST(ScenesConvertCli, AValueThatOverflowsOnceConvertedIsExitTwoAndWritesNothing) {
  TempDir dir;
  write(dir, "huge.nff",
        "v\nfrom 0 0 10\nat 0 0 0\nup 0 1 0\nangle 45\nhither 1\nresolution 8 8\n"
        "f 1 1 1 1 0 0 0 0\ns 1e308 1e308 1e308 1e308\n");
  const CliRun r =
      run_raygate({"scenes", "convert", "huge.nff", "--to", "obj", "-o", "x.obj"}, dir);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("huge.nff: a value overflows once converted"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.obj"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.mtl"));
}

TEST(ScenesConvertCli, UnknownFormatMissingFileAndBadViewAreExitTwo) {
  TempDir dir;
  write(dir, "in.nff", kScene);
  CliRun r = run_raygate({"scenes", "convert", "in.nff", "--to", "rib", "-o", "x.rib"}, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "raygate: error: --to: unknown format 'rib' (expected pov, obj or pbrt)\n");
  r = run_raygate({"scenes", "convert", "missing.nff", "--to", "pov", "-o", "x.pov"}, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("missing.nff"), std::string::npos);
  r = run_raygate({"scenes", "convert", "in.nff", "--to", "pov"}, dir);  // no -o
  EXPECT_EQ(r.exit_code, 2);
  write(dir, "view.nff", "v\nfrom 0 0 0\nat 0 0 1\nup 0 0 2\nangle 45\nhither 1\nresolution 8 8\n");
  r = run_raygate({"scenes", "convert", "view.nff", "--to", "pov", "-o", "x.pov"}, dir);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("'up' must not be parallel"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "x.pov"));
}

// The fifth sweep: `-o` naming the input (in any spelling, or a hard link to it), or an OBJ
// whose MTL is the input, replaced the scene it was converted from.
TEST(ScenesConvertCli, TheInputSceneIsNeverOverwritten) {
  TempDir dir;
  write(dir, "in.nff", kScene);
  std::filesystem::create_directory(dir.path() / "sub");
  std::filesystem::create_hard_link(dir.path() / "in.nff", dir.path() / "same.nff");
  write(dir, "in.mtl", kScene);
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"in.nff", "--to", "pov", "-o", "in.nff"},
        {"in.nff", "--to", "pbrt", "-o", "sub/../in.nff"},
        {"in.nff", "--to", "pov", "-o", "same.nff"},
        {"in.mtl", "--to", "obj", "-o", "in.obj"}}) {
    std::vector<std::string> command{"scenes", "convert"};
    command.insert(command.end(), args.begin(), args.end());
    const CliRun r = run_raygate(command, dir);
    EXPECT_EQ(r.exit_code, 2) << args.back() << ": " << r.out;
    EXPECT_NE(r.out.find("name the same file"), std::string::npos) << r.out;
  }
  EXPECT_EQ(read_file(dir.path() / "in.nff"), kScene);
  EXPECT_EQ(read_file(dir.path() / "in.mtl"), kScene);
}

}  // namespace
}  // namespace raygate::test

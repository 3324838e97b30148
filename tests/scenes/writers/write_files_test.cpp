// Writing converted scenes to files: format names, the files written (OBJ with its MTL beside
// it), the same bytes on every run, and no file at all when the scene cannot be converted.
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "core/fs.h"
#include "spd.h"
#include "writer_test_support.h"

namespace raygate::writers {
namespace {

TEST(WriteSceneFiles, FormatNamesRoundTrip) {
  for (OutputFormat f : {OutputFormat::pov, OutputFormat::obj, OutputFormat::pbrt}) {
    EXPECT_EQ(parse_output_format(format_name(f)), f);
  }
  EXPECT_FALSE(parse_output_format("POV").has_value());
  EXPECT_FALSE(parse_output_format("rib").has_value());
}

TEST(WriteSceneFiles, WritesTheStreamWritersOutput) {
  const TempDir dir;
  const nff::Scene scene = test::parse();
  auto files = write_scene_files(scene, OutputFormat::pov, dir.path() / "a.pov");
  EXPECT_EQ(files, std::vector<std::filesystem::path>{dir.path() / "a.pov"});
  EXPECT_EQ(read_file(files[0]), test::pov_text(scene));

  files = write_scene_files(scene, OutputFormat::obj, dir.path() / "sub" / "b.obj");
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[1], dir.path() / "sub" / "b.mtl");
  EXPECT_NE(read_file(files[0]).find("\nmtllib b.mtl\n"), std::string::npos);
  EXPECT_EQ(read_file(files[1]), test::mtl_text(scene));

  files = write_scene_files(scene, OutputFormat::pbrt, dir.path() / "c.pbrt");
  EXPECT_NE(read_file(files[0]).find("\"string filename\" [ \"c.exr\" ]"), std::string::npos);
}

TEST(WriteSceneFiles, SameSceneGivesTheSameBytes) {
  const nff::Scene first = test::parse();
  const nff::Scene second = test::parse();
  EXPECT_EQ(test::pov_text(first), test::pov_text(second));
  EXPECT_EQ(test::obj_text(first), test::obj_text(second));
  EXPECT_EQ(test::mtl_text(first), test::mtl_text(second));
  EXPECT_EQ(test::pbrt_text(first), test::pbrt_text(second));
  const TempDir dir;
  for (OutputFormat f : {OutputFormat::pov, OutputFormat::obj, OutputFormat::pbrt}) {
    const std::filesystem::path out = dir.path() / "scene.out";
    std::vector<std::string> bytes;
    for (const nff::Scene* scene : {&first, &second}) {
      for (const auto& file : write_scene_files(*scene, f, out)) bytes.push_back(read_file(file));
    }
    ASSERT_EQ(bytes.size() % 2, 0u);
    for (std::size_t i = 0; i < bytes.size() / 2; ++i) {
      EXPECT_EQ(bytes[i], bytes[i + bytes.size() / 2]) << format_name(f);
    }
  }
}

// Real SPD scenes: gears' concave 144-gons, teapot's patches (with zero-area ones at size 1).
TEST(WriteSceneFiles, SpdScenesGiveTheSameBytesTwice) {
  for (const char* name : {"gears", "teapot"}) {
    std::ostringstream text;
    scenes::generate(name, {.size = 1}, text);
    const nff::Scene first = nff::parse_nff(text.str(), name);
    const nff::Scene second = nff::parse_nff(text.str(), name);
    EXPECT_EQ(test::pov_text(first), test::pov_text(second)) << name;
    EXPECT_EQ(test::obj_text(first), test::obj_text(second)) << name;
    EXPECT_EQ(test::pbrt_text(first), test::pbrt_text(second)) << name;
  }
}

TEST(WriteSceneFiles, UnusableViewWritesNothing) {
  const TempDir dir;
  nff::Scene scene = test::parse();
  scene.view.up = scene.view.at - scene.view.from;
  for (OutputFormat f : {OutputFormat::pov, OutputFormat::obj, OutputFormat::pbrt}) {
    EXPECT_THROW(write_scene_files(scene, f, dir.path() / "x.out"), std::invalid_argument);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(WriteSceneFiles, ObjMustNotOverwriteItsOwnMtl) {
  const TempDir dir;
  EXPECT_THROW(write_scene_files(test::parse(), OutputFormat::obj, dir.path() / "x.mtl"),
               std::invalid_argument);
}

}  // namespace
}  // namespace raygate::writers

// The NFF reader on valid input: every entity's values and locations, the layouts the SPD
// writes (`b` before `v`, one-line `c`), the spec's layouts (three-line `c`), comments, and
// reading from disk.
#include "nff/parser.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

namespace raygate::nff {
namespace {

void expect_vec(const Vec3& v, double x, double y, double z) {
  EXPECT_EQ(v.x, x);
  EXPECT_EQ(v.y, y);
  EXPECT_EQ(v.z, z);
}

void expect_loc(const FileLoc& loc, int line, int column) {
  EXPECT_EQ(loc.path, "scene.nff");
  EXPECT_EQ(loc.line, line);
  EXPECT_EQ(loc.column, column);
}

// Lines are numbered in the comments so the expected locations can be checked by eye.
constexpr const char* kEveryEntity =
    "b 0.078 0.361 0.753\n"                   // 1
    "v\n"                                     // 2
    "from 2.1 1.3 1.7\n"                      // 3
    "at 0 0 0\n"                              // 4
    "up 0 0 1\n"                              // 5
    "angle 45\n"                              // 6
    "hither 0.01\n"                           // 7
    "resolution 640 480\n"                    // 8
    "l 4 3 2\n"                               // 9
    "l 1 -4 4 0.5 0.25 1\n"                   // 10
    "f 1 0.75 0.33 0.8 0 100000 0 1\n"        // 11
    "p 4\n"                                   // 12
    "12 12 -0.5\n"                            // 13
    "-12 12 -0.5\n"                           // 14
    "-12 -12 -0.5\n"                          // 15
    "12 -12 -0.5\n"                           // 16
    "  f 1 0.9 0.7 0.5 0.5 3.0827 0.5 1.5\n"  // 17
    "s 0 0 0 0.5\n"                           // 18
    "c 0 0 0 0.15 0 0 1 0.1005\n"             // 19
    "c\n"                                     // 20
    "1 2 3 4\n"                               // 21
    "5 6 7 8\n"                               // 22
    "pp 3\n"                                  // 23
    "0 0 0 0 0 1\n"                           // 24
    "1 0 0 0 -0 1\n"                          // 25
    "0 1 0 0 0.6 0.8\n";                      // 26

TEST(NffParser, ReadsEveryEntity) {
  const Scene scene = parse_nff(kEveryEntity, "scene.nff");
  EXPECT_EQ(scene.path, "scene.nff");
  expect_vec(scene.background, 0.078, 0.361, 0.753);

  expect_vec(scene.view.from, 2.1, 1.3, 1.7);
  expect_vec(scene.view.at, 0, 0, 0);
  expect_vec(scene.view.up, 0, 0, 1);
  EXPECT_EQ(scene.view.angle_degrees, 45.0);
  EXPECT_EQ(scene.view.hither, 0.01);
  EXPECT_EQ(scene.view.width, 640);
  EXPECT_EQ(scene.view.height, 480);

  ASSERT_EQ(scene.lights.size(), 2u);
  expect_vec(scene.lights[0].position, 4, 3, 2);
  EXPECT_FALSE(scene.lights[0].has_color);
  expect_vec(scene.lights[0].color, 1, 1, 1);
  expect_vec(scene.lights[1].position, 1, -4, 4);
  EXPECT_TRUE(scene.lights[1].has_color);
  expect_vec(scene.lights[1].color, 0.5, 0.25, 1);

  ASSERT_EQ(scene.materials.size(), 2u);
  const Material& floor = scene.materials[0];
  expect_vec(floor.color, 1, 0.75, 0.33);
  EXPECT_EQ(floor.kd, 0.8);
  EXPECT_EQ(floor.ks, 0.0);
  EXPECT_EQ(floor.shine, 100000.0);
  EXPECT_EQ(floor.transmittance, 0.0);
  EXPECT_EQ(floor.ior, 1.0);
  expect_loc(floor.loc, 11, 1);
  const Material& shiny = scene.materials[1];
  expect_vec(shiny.color, 1, 0.9, 0.7);
  EXPECT_EQ(shiny.kd, 0.5);
  EXPECT_EQ(shiny.ks, 0.5);
  EXPECT_EQ(shiny.shine, 3.0827);
  EXPECT_EQ(shiny.transmittance, 0.5);
  EXPECT_EQ(shiny.ior, 1.5);
  expect_loc(shiny.loc, 17, 3);

  ASSERT_EQ(scene.polygons.size(), 1u);
  const Polygon& quad = scene.polygons[0];
  ASSERT_EQ(quad.vertices.size(), 4u);
  expect_vec(quad.vertices[0], 12, 12, -0.5);
  expect_vec(quad.vertices[1], -12, 12, -0.5);
  expect_vec(quad.vertices[2], -12, -12, -0.5);
  expect_vec(quad.vertices[3], 12, -12, -0.5);
  EXPECT_EQ(quad.material, 0);
  expect_loc(quad.loc, 12, 1);

  ASSERT_EQ(scene.spheres.size(), 1u);
  expect_vec(scene.spheres[0].center, 0, 0, 0);
  EXPECT_EQ(scene.spheres[0].radius, 0.5);
  EXPECT_EQ(scene.spheres[0].material, 1);
  expect_loc(scene.spheres[0].loc, 18, 1);

  ASSERT_EQ(scene.cones.size(), 2u);
  const Cone& one_line = scene.cones[0];
  expect_vec(one_line.base, 0, 0, 0);
  EXPECT_EQ(one_line.base_radius, 0.15);
  expect_vec(one_line.apex, 0, 0, 1);
  EXPECT_EQ(one_line.apex_radius, 0.1005);
  expect_loc(one_line.loc, 19, 1);
  const Cone& three_lines = scene.cones[1];
  expect_vec(three_lines.base, 1, 2, 3);
  EXPECT_EQ(three_lines.base_radius, 4.0);
  expect_vec(three_lines.apex, 5, 6, 7);
  EXPECT_EQ(three_lines.apex_radius, 8.0);
  EXPECT_EQ(three_lines.material, 1);
  expect_loc(three_lines.loc, 20, 1);

  ASSERT_EQ(scene.patches.size(), 1u);
  const Patch& patch = scene.patches[0];
  ASSERT_EQ(patch.vertices.size(), 3u);
  ASSERT_EQ(patch.normals.size(), 3u);
  expect_vec(patch.vertices[1], 1, 0, 0);
  expect_vec(patch.normals[1], 0, 0, 1);
  EXPECT_TRUE(std::signbit(patch.normals[1].y));  // "-0" is kept as written
  expect_vec(patch.vertices[2], 0, 1, 0);
  expect_vec(patch.normals[2], 0, 0.6, 0.8);
  expect_loc(patch.loc, 23, 1);

  EXPECT_EQ(scene.primitive_count(), 5u);
}

TEST(NffParser, ViewDefaultsAndAnyOrder) {
  const Scene scene = parse_nff(
      "v angle 30 up 0 1 0 at 1 2 3 from 4 5 6\nf 1 1 1 1 0 1 0 1\ns 0 0 0 1\n", "scene.nff");
  expect_vec(scene.view.from, 4, 5, 6);
  expect_vec(scene.view.at, 1, 2, 3);
  expect_vec(scene.view.up, 0, 1, 0);
  EXPECT_EQ(scene.view.angle_degrees, 30.0);
  EXPECT_EQ(scene.view.hither, 0.0);
  EXPECT_EQ(scene.view.width, 512);
  EXPECT_EQ(scene.view.height, 512);
  expect_vec(scene.background, 0, 0, 0);  // no `b`: black
  EXPECT_TRUE(scene.lights.empty());
}

TEST(NffParser, ViewOnlyIsAValidScene) {
  const Scene scene = parse_nff("v from 0 0 1 at 0 0 0 up 0 1 0 angle 45", "scene.nff");
  EXPECT_EQ(scene.primitive_count(), 0u);
}

TEST(NffParser, CommentsAnywhere) {
  const Scene scene = parse_nff(
      "# a scene\n"
      "v # the view\n"
      "from 0 0 -5#no space before the comment\n"
      "at 0 0 0 up 0 1 0 angle 45 # at, up and angle on one line\n"
      "#f 0 0 0 0 0 0 0 0\n"
      "f 1 1 1 1 0 1 0 1\n"
      "s 1 2 # the radius is on the next line\n"
      "3 4\n"
      "# no newline at the end",
      "scene.nff");
  EXPECT_EQ(scene.view.from.z, -5.0);
  ASSERT_EQ(scene.materials.size(), 1u);
  expect_loc(scene.materials[0].loc, 6, 1);
  ASSERT_EQ(scene.spheres.size(), 1u);
  expect_vec(scene.spheres[0].center, 1, 2, 3);
  EXPECT_EQ(scene.spheres[0].radius, 4.0);
  expect_loc(scene.spheres[0].loc, 7, 1);
}

TEST(NffParser, WhitespaceVariantsAndColumns) {
  // CRLF line ends, tabs, and a form feed are all separators; columns count bytes.
  const Scene scene = parse_nff(
      "v\r\nfrom 0 0 -5\r\nat 0 0 0\r\nup 0 1 0\r\nangle 45\r\n\tf 1 1 1 1 0 1 0 1\f\r\n"
      "   s\t0 0 0 1\r\n",
      "scene.nff");
  expect_loc(scene.materials[0].loc, 6, 2);
  expect_loc(scene.spheres[0].loc, 7, 4);
}

TEST(NffParser, ByteOrderMarkIsSkipped) {
  const Scene scene = parse_nff(
      "\xEF\xBB\xBF"
      "f 1 1 1 1 0 1 0 1\nv from 0 0 1 at 0 0 0 up 0 1 0 angle 45\n",
      "scene.nff");
  expect_loc(scene.materials[0].loc, 1, 1);
}

TEST(NffParser, NumberSpellings) {
  const Scene scene = parse_nff(
      "v from 1e+06 -2.22045e-16 +1.5 at .5 5. -0 up 0 0 1E2 angle 45\n"
      "f 1 1 1 1 0 1 0 1\n"
      "s 1e-999 -1e-999 1e-310 0.5\n",
      "scene.nff");
  expect_vec(scene.view.from, 1e6, -2.22045e-16, 1.5);
  expect_vec(scene.view.at, 0.5, 5.0, 0.0);
  EXPECT_TRUE(std::signbit(scene.view.at.z));
  EXPECT_EQ(scene.view.up.z, 100.0);
  // Too small for a double: read as (signed) zero rather than rejected.
  EXPECT_EQ(scene.spheres[0].center.x, 0.0);
  EXPECT_TRUE(std::signbit(scene.spheres[0].center.y));
  EXPECT_EQ(scene.spheres[0].center.z, 1e-310);
}

TEST(NffParser, ObjectsUseTheMaterialInForce) {
  const Scene scene = parse_nff(
      "v from 0 0 1 at 0 0 0 up 0 1 0 angle 45\n"
      "f 1 0 0 1 0 1 0 1\ns 0 0 0 1\ns 0 0 1 1\n"
      "f 0 1 0 1 0 1 0 1\ns 0 0 2 1\nl 1 1 1\nc 0 0 0 1 0 0 1 1\n",
      "scene.nff");
  ASSERT_EQ(scene.spheres.size(), 3u);
  EXPECT_EQ(scene.spheres[0].material, 0);
  EXPECT_EQ(scene.spheres[1].material, 0);
  EXPECT_EQ(scene.spheres[2].material, 1);
  EXPECT_EQ(scene.cones[0].material, 1);
  EXPECT_EQ(scene.lights.size(), 1u);  // a light after objects is accepted
}

TEST(NffParser, InsideVisibleAndConePrimitives) {
  const Scene scene = parse_nff(
      "v from 0 0 1 at 0 0 0 up 0 1 0 angle 45\nf 1 1 1 1 0 1 0 1\n"
      "s 0 0 0 -1\nc 0 0 0 -1 0 0 1 -0.5\nc 0 0 0 1 0 0 1 0\nc 0 0 0 0 0 0 1 -2\n",
      "scene.nff");
  EXPECT_EQ(scene.spheres[0].radius, -1.0);
  ASSERT_EQ(scene.cones.size(), 3u);
  EXPECT_EQ(scene.cones[0].apex_radius, -0.5);
  EXPECT_EQ(scene.cones[1].apex_radius, 0.0);
  EXPECT_EQ(scene.cones[2].apex_radius, -2.0);
}

// A gear's top face (spd-spec.md §3.2): 144 vertices, concave.
TEST(NffParser, ConcavePolygonWithManyVertices) {
  std::string text = "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45\nf 1 1 1 1 0 1 0 1\np 144\n";
  const double pi = 3.14159265358979323846;
  const double a = 2 * pi / 36;
  for (int k = 0; k < 36; ++k) {
    const double g = 2 * pi * k / 36;
    for (const auto& [radius, angle] :
         {std::pair{0.995, g - 0.19 * a}, std::pair{0.995, g + 0.19 * a},
          std::pair{0.9, g + 0.3 * a}, std::pair{0.9, g + 0.7 * a}}) {
      char line[96];
      std::snprintf(line, sizeof line, "%.17g %.17g 1\n", radius * std::cos(angle),
                    radius * std::sin(angle));
      text += line;
    }
  }
  const Scene scene = parse_nff(text, "scene.nff");
  ASSERT_EQ(scene.polygons.size(), 1u);
  EXPECT_EQ(scene.polygons[0].vertices.size(), 144u);
  EXPECT_NEAR(scene.polygons[0].vertices[0].x, 0.995 * std::cos(-0.19 * a), 1e-15);
}

// The SPD writes `pp` uncleaned: its teapot at size 1 has zero-area triangles (spd-spec.md §8).
// They are legal input, kept as written; the tracer never hits them.
TEST(NffParser, DegeneratePatchesAreAccepted) {
  const Scene scene = parse_nff(
      "v from 0 0 5 at 0 0 0 up 0 1 0 angle 45\nf 1 1 1 1 0 1 0 1\n"
      "pp 3\n2.7 0 2.4 -0.6 0 0.8\n3.3 0 2.4 0.38 0 -0.92\n3.2 0 2.4 -0.41 0 0.91\n"
      "pp 3\n0 0 0 0 0 1\n0 0 0 0 0 1\n1 0 0 0 0 1\n",
      "scene.nff");
  EXPECT_EQ(scene.patches.size(), 2u);
}

// About the size of the teapot at size 12 (1.5 MB); prints the time so it can be watched.
TEST(NffParser, LargeSceneIsFast) {
  std::string text =
      "b 0.078 0.361 0.753\nv\nfrom 0 0 5\nat 0 0 0\nup 0 1 0\nangle 45\n"
      "hither 1\nresolution 512 512\nl 1 2 3\nf 1 1 1 1 0 1 0 1\n";
  int patches = 0;
  while (text.size() < 1'500'000) {
    const double t = patches * 1e-4;
    char entry[256];
    std::snprintf(entry, sizeof entry,
                  "pp 3\n%g %g %g -0.267261 0.534522 0.801784\n%g %g %g -0.267261 0.534522 "
                  "0.801784\n%g %g %g -0.267261 0.534522 0.801784\n",
                  t, 0.1 + t, 1.23456, 1.5 + t, -0.25, 2.5 - t, 0.75, 1 + t, -3.125);
    text += entry;
    ++patches;
  }
  const auto start = std::chrono::steady_clock::now();
  const Scene scene = parse_nff(text, "scene.nff");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(scene.patches.size(), static_cast<std::size_t>(patches));
  std::printf("parsed %zu bytes (%d patches) in %.3f s\n", text.size(), patches, seconds);
  RecordProperty("parse_seconds", std::to_string(seconds));
}

TEST(NffParser, ReadsAFile) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("raygate_nff_read_" + std::to_string(::getpid()) + ".nff");
  {
    std::ofstream out(path, std::ios::binary);
    out << kEveryEntity;
  }
  const Scene scene = read_nff_file(path.string());
  std::filesystem::remove(path);
  EXPECT_EQ(scene.path, path.string());
  ASSERT_EQ(scene.spheres.size(), 1u);
  EXPECT_EQ(scene.spheres[0].loc.path, path.string());
  EXPECT_EQ(scene.spheres[0].loc.line, 18);
}

}  // namespace
}  // namespace raygate::nff

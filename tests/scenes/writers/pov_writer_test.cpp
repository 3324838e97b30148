// The POV-Ray 3.7 writer: a camera whose rays are raygate-baseline's (so the right-handed scene
// is not mirrored in left-handed POV-Ray), lights at 1/sqrt(n), one material per `f`, spheres,
// open cones, concave polygons as triangles and patches as smooth triangles.
#include <gtest/gtest.h>

#include <cmath>

#include "render/camera.h"
#include "writer_test_support.h"

namespace raygate::writers {
namespace {

using test::count;
using test::lines_starting;
using test::numbers_after;

Vec3 vec3(const std::vector<double>& v) { return {v.at(0), v.at(1), v.at(2)}; }

// POV-Ray's perspective camera: direction + (x/W - 1/2)·right + (1/2 - y/H)·up.
TEST(PovWriter, CameraShootsTheBaselinesRays) {
  // The tetra view: `up` not perpendicular to the view; and a wide image.
  nff::Scene scene = test::parse();
  scene.view.from = {1.02285, -3.17715, -2.17451};
  scene.view.at = {-0.004103, -0.004103, 0.216539};
  scene.view.up = {-0.816497, -0.816497, 0.816497};
  const std::string pov = test::pov_text(scene);
  const Vec3 location = vec3(numbers_after(pov, "  location"));
  const Vec3 direction = vec3(numbers_after(pov, "  direction"));
  const Vec3 right = vec3(numbers_after(pov, "  right"));
  const Vec3 up = vec3(numbers_after(pov, "  up"));
  EXPECT_EQ(location, scene.view.from);

  const render::Camera baseline = render::make_camera(scene.view);
  for (const auto& [x, y] : {std::pair{0.5, 0.5}, std::pair{63.5, 0.5}, std::pair{10.5, 40.5},
                             std::pair{32.0, 24.0}, std::pair{63.5, 47.5}}) {
    const Vec3 pov_ray = normalize(direction + right * (x / 64.0 - 0.5) + up * (0.5 - y / 48.0));
    EXPECT_LT(length(pov_ray - baseline.direction_at(x, y)), 1e-9) << x << "," << y;
  }
}

TEST(PovWriter, HeaderBackgroundAndLights) {
  const std::string pov = test::pov_text(test::parse());
  EXPECT_EQ(pov.rfind("// POV-Ray 3.7 scene converted from scene.nff", 0), 0u);
  EXPECT_NE(pov.find("#version 3.7;\n"), std::string::npos);
  EXPECT_NE(pov.find("global_settings { assumed_gamma 1.0 max_trace_level 5 adc_bailout 0 }"),
            std::string::npos);
  EXPECT_NE(pov.find("background { color rgb <0.1, 0.2, 0.3> }"), std::string::npos);
  const auto lights = lines_starting(pov, "light_source");
  ASSERT_EQ(lights.size(), 2u);
  EXPECT_EQ(lights[0],
            "light_source { <5, -5, 5> color rgb <0.7071067812, 0.7071067812, 0.7071067812> }");
}

TEST(PovWriter, OneMaterialPerFillLine) {
  const std::string pov = test::pov_text(test::parse());
  EXPECT_EQ(count(pov, "#declare F"), 3u);
  // Diffuse + mirror: Phong highlight and reflection both weighted by Ks.
  EXPECT_NE(
      pov.find("#declare F1 = material {\n  texture {\n    pigment { rgb <1, 0, 0> }\n"
               "    finish { ambient 0.1 diffuse 0.7 phong 0.3 phong_size 20 reflection { 0.3 } }"),
      std::string::npos);
  // Transmitter: transmit T, ambient and diffuse divided by POV's opacity 1 - T, an ior.
  EXPECT_NE(pov.find("pigment { rgbt <0, 1, 0, 0.8> }\n    finish { ambient 0.5 diffuse 1 }\n"
                     "  }\n  interior { ior 1.5 }"),
            std::string::npos);
  EXPECT_NE(pov.find("pigment { rgb <0, 0, 1> }\n    finish { ambient 0.1 diffuse 1 }\n  }\n}"),
            std::string::npos);
}

TEST(PovWriter, SphereAndOpenCones) {
  const std::string pov = test::pov_text(test::parse());
  EXPECT_NE(pov.find("\nsphere { <1, 2, 3>, 0.5 material { F1 } }\n"), std::string::npos);
  EXPECT_NE(pov.find("\ncone { <0, 0, 0>, 1, <0, 0, 2>, 0.25 open material { F2 } }\n"),
            std::string::npos);
  EXPECT_NE(pov.find("\ncone { <1, 0, 0>, 0.5, <1, 0, 1>, 0.5 open material { F2 } }\n"),
            std::string::npos);
}

TEST(PovWriter, ConcavePolygonBecomesSixTriangles) {
  const std::string pov = test::pov_text(test::parse());
  const auto triangles = lines_starting(pov, "triangle {");
  EXPECT_EQ(triangles.size(), 6u);  // 8 vertices - 2
  for (const std::string& t : triangles) EXPECT_NE(t.find("material { F3 } }"), std::string::npos);
}

TEST(PovWriter, PatchBecomesSmoothTriangleWithItsNormals) {
  const std::string pov = test::pov_text(test::parse());
  const auto smooth = lines_starting(pov, "smooth_triangle");
  ASSERT_EQ(smooth.size(), 1u);
  EXPECT_EQ(smooth[0],
            "smooth_triangle { <0, 0, 1>, <0, 0, 1>, <1, 0, 1>, <0.6, 0, 0.8>, <0, 1, 1>, "
            "<0, 0.6, 0.8> material { F3 } }");
}

TEST(PovWriter, DegeneratePrimitivesAreSkippedAndCounted) {
  nff::Scene scene = test::parse();
  scene.spheres.push_back({{0, 0, 0}, 0.0, 0, {}});
  scene.patches.push_back(
      {{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, 0, {}});
  const std::string pov = test::pov_text(scene);
  EXPECT_EQ(lines_starting(pov, "sphere").size(), 1u);
  EXPECT_NE(pov.find("// 2 degenerate primitive(s) skipped"), std::string::npos);
}

}  // namespace
}  // namespace raygate::writers

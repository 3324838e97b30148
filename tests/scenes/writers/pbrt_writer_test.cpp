// The pbrt-v4 writer. pbrt-v4 is left-handed; the camera test follows pbrt-v4's own conventions
// (LookAt's camera x axis is normalize(up x dir); raster x grows with camera x, raster y with
// -camera y; `fov` spans the shorter image side) to show that `Scale -1 1 1` before `LookAt`
// gives every pixel raygate-baseline's ray, unmirrored.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/camera.h"
#include "writer_test_support.h"

namespace raygate::writers {
namespace {

using test::lines_starting;
using test::numbers_after;

// The direction pbrt-v4 shoots through raster position (x, y) for the written camera.
Vec3 pbrt_ray(const std::string& pbrt, int width, int height, double x, double y) {
  const std::vector<double> scale = numbers_after(pbrt, "Scale");
  const std::vector<double> look = numbers_after(pbrt, "LookAt");
  const double fov = numbers_after(pbrt, "Camera \"perspective\" \"float fov\"").at(0);
  const Vec3 from{look[0], look[1], look[2]};
  const Vec3 dir = normalize(Vec3{look[3], look[4], look[5]} - from);
  const Vec3 right = normalize(cross(normalize(Vec3{look[6], look[7], look[8]}), dir));
  const Vec3 new_up = cross(dir, right);
  // Screen window: [-aspect, aspect] x [-1, 1] for wide images, [-1, 1] x [-1/aspect, 1/aspect]
  // for tall ones; the perspective divides by tan(fov / 2).
  const double aspect = double(width) / height;
  const double sx_max = aspect > 1.0 ? aspect : 1.0;
  const double sy_max = aspect > 1.0 ? 1.0 : 1.0 / aspect;
  const double t = std::tan(fov * std::numbers::pi / 360.0);
  const double sx = -sx_max + 2.0 * sx_max * x / width;
  const double sy = sy_max - 2.0 * sy_max * y / height;
  const Vec3 camera{sx * t, sy * t, 1.0};
  // world-from-camera = inverse(Scale * LookAt) = LookAt^-1 * Scale^-1.
  const Vec3 scaled{camera.x / scale.at(0), camera.y / scale.at(1), camera.z / scale.at(2)};
  return normalize(right * scaled.x + new_up * scaled.y + dir * scaled.z);
}

void expect_baseline_rays(const nff::Scene& scene) {
  const std::string pbrt = test::pbrt_text(scene);
  const render::Camera baseline = render::make_camera(scene.view);
  const int w = scene.view.width;
  const int h = scene.view.height;
  for (const auto& [x, y] : {std::pair{0.5, 0.5}, std::pair{w - 0.5, 0.5}, std::pair{10.5, h - 3.5},
                             std::pair{w / 2.0, h / 2.0}}) {
    EXPECT_LT(length(pbrt_ray(pbrt, w, h, x, y) - baseline.direction_at(x, y)), 1e-9)
        << w << "x" << h << " at " << x << "," << y;
  }
}

TEST(PbrtWriter, CameraIsUnmirroredForWideAndTallImages) {
  nff::Scene scene = test::parse();  // 64 x 48
  expect_baseline_rays(scene);
  scene.view.width = 40;
  scene.view.height = 90;
  expect_baseline_rays(scene);
  scene.view.up = {0.2, 1, 0};  // lattice-like: `up` not perpendicular to the view
  scene.view.from = {0.5, 1, 0.5};
  scene.view.at = {0.5, -1, -1.5};
  expect_baseline_rays(scene);
}

TEST(PbrtWriter, OptionsAndLights) {
  const std::string pbrt = test::pbrt_text(test::parse());
  EXPECT_EQ(lines_starting(pbrt, "Scale -1 1 1").size(), 1u);
  EXPECT_NE(pbrt.find("\"integer xresolution\" [ 64 ] \"integer yresolution\" [ 48 ] "
                      "\"string filename\" [ \"scene.exr\" ]"),
            std::string::npos);
  EXPECT_NE(pbrt.find("Integrator \"path\" \"integer maxdepth\" [ 5 ]\nWorldBegin\n"),
            std::string::npos);
  EXPECT_NE(pbrt.find("LightSource \"infinite\" \"rgb L\" [ 0.1 0.2 0.3 ]"), std::string::npos);
  const auto lights = lines_starting(pbrt, "LightSource \"point\"");
  ASSERT_EQ(lights.size(), 2u);
  // 1/sqrt(2) each, times pi·d² (d: light to look-at point) against pbrt's falloff and R/pi.
  const std::vector<double> v = test::numbers_in(lights[0]);
  ASSERT_EQ(v.size(), 7u);
  EXPECT_NEAR(v[6], std::numbers::pi * 75.0 / std::sqrt(2.0), 1e-6);
}

TEST(PbrtWriter, MaterialsAreApproximatedByKind) {
  const std::string pbrt = test::pbrt_text(test::parse());
  // Kd 0.7 + Ks 0.3: a mix choosing the mirror 30% of the time.
  EXPECT_NE(pbrt.find("MakeNamedMaterial \"f1-diffuse\" \"string type\" \"diffuse\" "
                      "\"rgb reflectance\" [ 1 0 0 ]\n"),
            std::string::npos);
  EXPECT_NE(pbrt.find("MakeNamedMaterial \"f1-mirror\" \"string type\" \"conductor\" "
                      "\"rgb reflectance\" [ 1 1 1 ] \"float roughness\" [ 0 ]\n"),
            std::string::npos);
  EXPECT_NE(pbrt.find("MakeNamedMaterial \"f1\" \"string type\" \"mix\" \"string materials\" "
                      "[ \"f1-diffuse\" \"f1-mirror\" ] \"float amount\" [ 0.3 ]\n"),
            std::string::npos);
  EXPECT_NE(
      pbrt.find("MakeNamedMaterial \"f2\" \"string type\" \"dielectric\" \"float eta\" [ 1.5 ]"),
      std::string::npos);
  EXPECT_NE(
      pbrt.find(
          "MakeNamedMaterial \"f3\" \"string type\" \"diffuse\" \"rgb reflectance\" [ 0 0 1 ]"),
      std::string::npos);
}

TEST(PbrtWriter, SphereIsTranslatedAndCylinderTransformedOntoItsAxis) {
  const std::string pbrt = test::pbrt_text(test::parse());
  EXPECT_NE(pbrt.find("NamedMaterial \"f1\"\nAttributeBegin\n  Translate 1 2 3\n"
                      "  Shape \"sphere\" \"float radius\" [ 0.5 ]\nAttributeEnd\n"),
            std::string::npos);
  const std::vector<double> m = numbers_after(pbrt, "  ConcatTransform");
  ASSERT_EQ(m.size(), 16u);
  // pbrt transposes the 16 numbers: point' = sum_j m[4j + i] p_j + m[12 + i].
  const auto apply = [&m](const Vec3& p) {
    Vec3 r;
    for (int i = 0; i < 3; ++i) {
      const double v = m[i] * p.x + m[4 + i] * p.y + m[8 + i] * p.z + m[12 + i];
      (i == 0 ? r.x : (i == 1 ? r.y : r.z)) = v;
    }
    return r;
  };
  EXPECT_LT(length(apply({0, 0, 0}) - Vec3{1, 0, 0}), 1e-9);            // base
  EXPECT_LT(length(apply({0, 0, 1}) - Vec3{1, 0, 1}), 1e-9);            // apex (zmax is the height)
  EXPECT_NEAR(length(apply({1, 0, 0}) - apply({0, 0, 0})), 1.0, 1e-9);  // no scaling
  EXPECT_NE(pbrt.find("Shape \"cylinder\" \"float radius\" [ 0.5 ] \"float zmin\" [ 0 ] "
                      "\"float zmax\" [ 1 ]"),
            std::string::npos);
}

TEST(PbrtWriter, ConeIsATriangleMeshAndPatchKeepsNormals) {
  const std::string pbrt = test::pbrt_text(test::parse(), {.segments = 8});
  EXPECT_EQ(test::count(pbrt, "Shape \"trianglemesh\""), 3u);  // cone, polygon, patch
  EXPECT_EQ(test::count(pbrt, "\"normal N\""), 2u);            // cone, patch
  EXPECT_NE(pbrt.find("  \"point3 P\" [ 0 0 1 1 0 1 0 1 1 ]\n  \"normal N\" [ 0 0 1 0.6 0 0.8 0 "
                      "0.6 0.8 ]\n  \"integer indices\" [ 0 1 2 ]\n"),
            std::string::npos);
  const auto indices = lines_starting(pbrt, "  \"integer indices\"");
  ASSERT_EQ(indices.size(), 3u);
  EXPECT_EQ(test::numbers_in(indices[0]).size(), 3u * 16u);  // cone: 8 quads
  EXPECT_EQ(test::numbers_in(indices[1]).size(), 3u * 6u);   // concave octagon: 6 triangles
}

}  // namespace
}  // namespace raygate::writers

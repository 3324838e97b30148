// The pinhole camera of spd-spec.md §1.3: basis, handedness, pixel mapping, hither, aspect.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/camera.h"
#include "render/world.h"
#include "scene_builder.h"

namespace raygate::render {
namespace {

void expect_vec_near(const Vec3& a, const Vec3& b, double tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(Camera, BasisIsRightHandedWithUpMadePerpendicular) {
  // Looking along +y with a tilted up: up is straightened, right = forward x up = +x.
  const nff::Scene scene = test::make_scene({0, -5, 0}, {0, 0, 0}, {0, 0.7, 1}, 45, 16, 16);
  const Camera camera = make_camera(scene.view);
  expect_vec_near(camera.forward, {0, 1, 0}, 1e-15);
  expect_vec_near(camera.up, {0, 0, 1}, 1e-15);
  expect_vec_near(camera.right, {1, 0, 0}, 1e-15);
}

// spd-spec.md §1.3: in rings the front object at x = 0, seen from x = -1 looking along +y,
// appears right of centre.
TEST(Camera, RingsFrontObjectAppearsRightOfCentre) {
  const nff::Scene scene =
      test::make_scene({-1, -2.61313, 0.5}, {-1, -1.61313, 0.5}, {0, 0, 1}, 45, 512, 512);
  const Camera camera = make_camera(scene.view);
  const Vec3 to_object = Vec3{0, 2, 0.5} - camera.eye;
  EXPECT_GT(dot(to_object, camera.right), 0.0);
}

TEST(Camera, PixelCentresFollowTheDocumentedFormula) {
  const double angle = 60.0;
  const int width = 8;
  const int height = 4;
  const nff::Scene scene = test::make_scene({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, angle, width, height);
  const Camera camera = make_camera(scene.view);
  const double t = std::tan(angle * std::numbers::pi / 360.0);
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width; ++i) {
      const double sx = (2.0 * (i + 0.5) / width - 1.0) * t;
      const double sy = (1.0 - 2.0 * (j + 0.5) / height) * t * height / width;
      // forward -z, up +y, right = (-z) x (+y) = +x
      expect_vec_near(camera.direction_at(i + 0.5, j + 0.5), normalize(Vec3{sx, sy, -1}), 1e-15);
    }
  }
}

TEST(Camera, CornerRaysOfAFullImageSpanTheFieldOfView) {
  const nff::Scene scene = test::make_scene({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 16, 16);
  const Camera camera = make_camera(scene.view);
  expect_vec_near(camera.direction_at(0, 8), normalize(Vec3{-1, 0, -1}), 1e-15);
  expect_vec_near(camera.direction_at(16, 8), normalize(Vec3{1, 0, -1}), 1e-15);
  expect_vec_near(camera.direction_at(8, 0), normalize(Vec3{0, 1, -1}), 1e-15);
}

TEST(Camera, HitherBoundsDistanceAlongTheViewDirection) {
  nff::Scene scene = test::make_scene({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 90, 16, 16);
  scene.view.hither = 2.0;
  const Camera camera = make_camera(scene.view);
  const Ray centre = camera.ray_at(8, 8);
  EXPECT_DOUBLE_EQ(camera.t_min(centre), 2.0);
  const Ray edge = camera.ray_at(16, 8);  // 45 degrees off axis
  EXPECT_NEAR(camera.t_min(edge), 2.0 * std::sqrt(2.0), 1e-14);
}

TEST(Camera, UnusableViewsAreSceneErrors) {
  const auto view_with = [](auto change) {
    nff::Scene scene = test::make_scene({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, 45, 16, 16);
    change(scene.view);
    return scene.view;
  };
  EXPECT_THROW(make_camera(view_with([](nff::View& v) { v.at = v.from; })), SceneError);
  EXPECT_THROW(make_camera(view_with([](nff::View& v) { v.up = {0, 0, 3}; })), SceneError);
  EXPECT_THROW(make_camera(view_with([](nff::View& v) { v.angle_degrees = 180; })), SceneError);
  EXPECT_THROW(make_camera(view_with([](nff::View& v) { v.angle_degrees = 0; })), SceneError);
  EXPECT_THROW(make_camera(view_with([](nff::View& v) { v.width = 0; })), SceneError);
  EXPECT_THROW(make_camera(view_with([](nff::View& v) { v.height = 100000; })), SceneError);
}

}  // namespace
}  // namespace raygate::render

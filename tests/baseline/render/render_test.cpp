// Whole-image properties: camera orientation in the image, corner sampling, bit-identical
// images and ray counts between `--accel none` and `--accel bbox`, determinism, ray counts.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "render/render.h"
#include "scene_builder.h"

namespace raygate::render {
namespace {

using test::add_cone;
using test::add_light;
using test::add_material;
using test::add_patch;
using test::add_polygon;
using test::add_sphere;

Image render_scene(const nff::Scene& scene, RenderStats& stats, const RenderOptions& options) {
  return render(build_world(scene), make_camera(scene.view), options, stats);
}

// The pixel where channel `c` is largest.
std::pair<int, int> brightest(const Image& image, int channel) {
  std::pair<int, int> best{0, 0};
  float best_value = -1.0f;
  for (int j = 0; j < image.height; ++j) {
    for (int i = 0; i < image.width; ++i) {
      const float v = image.rgb[image.offset(i, j) + channel];
      if (v > best_value) {
        best_value = v;
        best = {i, j};
      }
    }
  }
  return best;
}

// Looking along +y with z up, +x is to the right and +z is up in the image.
TEST(RenderImage, ObjectsToTheRightAndAboveAppearRightAndUp) {
  nff::Scene scene = test::make_scene({0, -10, 0}, {0, 0, 0}, {0, 0, 1}, 40, 64, 48);
  add_sphere(scene, {2, 0, 0}, 0.5, add_material(scene, {{1, 0, 0}, 1}));
  add_sphere(scene, {0, 0, 2}, 0.5, add_material(scene, {{0, 1, 0}, 1}));
  add_light(scene, {0, -10, 0});
  RenderStats stats;
  const Image image = render_scene(scene, stats, {});
  const auto [red_x, red_y] = brightest(image, 0);
  const auto [green_x, green_y] = brightest(image, 1);
  EXPECT_GT(red_x, 40);
  EXPECT_NEAR(red_y, 24, 2);
  EXPECT_LT(green_y, 12);
  EXPECT_NEAR(green_x, 32, 2);
}

nff::Scene spheres_scene() {
  nff::Scene scene =
      test::make_scene({6, -8, 5}, {0, 0, 0.5}, {0, 0, 1}, 45, 40, 30, {0.1, 0.2, 0.4});
  const int floor = add_material(scene, {{0.9, 0.9, 0.8}, 0.8, 0.2, 3.0827});
  const int mirror = add_material(scene, {{0.8, 0.8, 0.8}, 0.2, 0.8, 45.2776});
  const int glass = add_material(scene, {{1, 1, 1}, 0.1, 0.1, 101.148, 0.9, 1.5});
  const int matte = add_material(scene, {{0.9, 0.3, 0.2}, 0.9});
  add_polygon(scene, test::square_z(-100, -100, 100, 100, 0), floor);
  const int kinds[3] = {mirror, glass, matte};
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) {
      add_sphere(scene, {-3.0 + 2 * a, -3.0 + 2 * b, 0.6}, 0.6, kinds[(a + b) % 3]);
    }
  }
  add_sphere(scene, {0, 0, 0.6}, 0.6, mirror);  // touches/overlaps others: ties, contacts
  add_light(scene, {-5, -6, 8});
  add_light(scene, {6, -3, 5});
  return scene;
}

nff::Scene cones_scene() {
  nff::Scene scene = test::make_scene({5, -7, 4}, {0, 0, 0.8}, {0, 0, 1}, 50, 40, 40);
  const int floor = add_material(scene, {{0.7, 0.7, 0.7}, 0.9});
  const int shiny = add_material(scene, {{0.2, 0.8, 0.3}, 0.6, 0.4, 11.1434});
  const int glass = add_material(scene, {{1, 1, 1}, 0.05, 0.1, 45.2776, 0.85, 1.33});
  add_polygon(scene, test::square_z(-5, -5, 5, 5, 0), floor);
  add_cone(scene, {-2, 0, 0}, 0.8, {-2, 0, 2}, 0.0, shiny);
  add_cone(scene, {0, 1, 0}, 0.5, {0, 1, 1.5}, 0.5, shiny);
  add_cone(scene, {2, -1, 0}, 0.5, {2, -1, 1.5}, 0.5, glass);
  add_cone(scene, {-1, -2, 1.5}, 0.0, {1, -2.5, 0.3}, 0.4, shiny);  // tilted, point at base
  add_cone(scene, {1, 2, 0.2}, -0.3, {1.5, 2, 1.8}, -0.1, glass);   // inside-visible radii
  add_light(scene, {-4, -5, 7});
  add_light(scene, {5, -2, 6});
  add_light(scene, {0, 3, 4});
  return scene;
}

// Five-pointed stars (concave, 10 vertices) at several orientations.
std::vector<Vec3> star(Vec3 centre, Vec3 u, Vec3 v, double outer, double inner) {
  std::vector<Vec3> points;
  for (int k = 0; k < 10; ++k) {
    const double r = k % 2 == 0 ? outer : inner;
    const double a = std::numbers::pi / 2 + k * std::numbers::pi / 5;
    points.push_back(centre + u * (r * std::cos(a)) + v * (r * std::sin(a)));
  }
  return points;
}

nff::Scene polygons_scene() {
  nff::Scene scene = test::make_scene({0, -8, 3}, {0, 0, 1}, {0, 0, 1}, 50, 40, 40);
  const int floor = add_material(scene, {{0.8, 0.8, 0.9}, 0.7, 0.3, 3.0827});
  const int star_material = add_material(scene, {{0.8, 0.2, 0.8}, 0.7, 0.3, 11.1434});
  const int glass = add_material(scene, {{1, 1, 1}, 0.05, 0.1, 45.2776, 0.9, 1.5});
  add_polygon(scene, test::square_z(-6, -6, 6, 6, 0), floor);
  add_polygon(scene, star({-2, 0, 1.5}, {1, 0, 0}, {0, 0, 1}, 1.2, 0.5), star_material);
  add_polygon(scene, star({1.5, 1, 1.2}, normalize(Vec3{1, 1, 0}), {0, 0, 1}, 1.0, 0.4), glass);
  add_polygon(scene, star({0, -1, 0.01}, {1, 0, 0}, {0, 1, 0}, 1.5, 0.6), star_material);
  add_light(scene, {-3, -6, 6});
  add_light(scene, {4, -4, 3});
  return scene;
}

// A smooth, glassy, lat-long sphere of pp triangles, plus pp quads (triangulated).
nff::Scene patches_scene() {
  nff::Scene scene = test::make_scene({3, -6, 3}, {0, 0, 1}, {0, 0, 1}, 45, 40, 40);
  const int floor = add_material(scene, {{0.8, 0.8, 0.8}, 0.8});
  const int glass = add_material(scene, {{1, 0.9, 0.8}, 0.1, 0.2, 45.2776, 0.8, 1.5});
  add_polygon(scene, test::square_z(-5, -5, 5, 5, 0), floor);
  const Vec3 centre{0, 0, 1};
  const int rings = 8;
  const int segments = 12;
  auto at = [&](int r, int s) {
    const double theta = std::numbers::pi * r / rings;
    const double phi = 2 * std::numbers::pi * s / segments;
    return Vec3{std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
  };
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      const Vec3 a = at(r, s), b = at(r + 1, s), c = at(r + 1, s + 1), d = at(r, s + 1);
      if (r > 0) add_patch(scene, {centre + a, centre + b, centre + d}, {a, b, d}, glass);
      if (r < rings - 1) add_patch(scene, {centre + b, centre + c, centre + d}, {b, c, d}, glass);
    }
  }
  const Vec3 up{0, 0.3, 1};
  add_patch(scene, {{2, -2, 0.5}, {3, -2, 0.5}, {3, -1, 0.8}, {2, -1, 0.8}}, {up, up, up, up},
            floor);
  add_light(scene, {-4, -5, 7});
  add_light(scene, {4, -4, 5});
  return scene;
}

void expect_same_image_and_rays(const nff::Scene& scene, Sampling sampling) {
  RenderStats plain;
  RenderStats boxed;
  const Image a = render_scene(scene, plain, {Accel::none, sampling, 5});
  const Image b = render_scene(scene, boxed, {Accel::bbox, sampling, 5});
  EXPECT_EQ(a.rgb, b.rgb);  // bit for bit
  EXPECT_EQ(plain.rays.eye, boxed.rays.eye);
  EXPECT_EQ(plain.rays.eye_hits, boxed.rays.eye_hits);
  EXPECT_EQ(plain.rays.shadow, boxed.rays.shadow);
  EXPECT_EQ(plain.rays.reflection, boxed.rays.reflection);
  EXPECT_EQ(plain.rays.refraction, boxed.rays.refraction);
  EXPECT_EQ(plain.tests.bbox_tests, 0u);
  EXPECT_GT(boxed.tests.bbox_tests, 0u);
  EXPECT_LT(boxed.tests.primitive_tests, plain.tests.primitive_tests);
  EXPECT_GT(plain.rays.shadow, 0u);
}

TEST(AccelEquivalence, Spheres) { expect_same_image_and_rays(spheres_scene(), Sampling::center); }
TEST(AccelEquivalence, Cones) { expect_same_image_and_rays(cones_scene(), Sampling::center); }
TEST(AccelEquivalence, ConcavePolygons) {
  expect_same_image_and_rays(polygons_scene(), Sampling::center);
}
TEST(AccelEquivalence, SmoothPatches) {
  expect_same_image_and_rays(patches_scene(), Sampling::center);
}
TEST(AccelEquivalence, CornerSampling) {
  expect_same_image_and_rays(spheres_scene(), Sampling::corners);
}

TEST(AccelEquivalence, ScenesExerciseSecondaryRays) {
  for (const nff::Scene& scene : {spheres_scene(), cones_scene(), patches_scene()}) {
    RenderStats stats;
    render_scene(scene, stats, {});
    EXPECT_GT(stats.rays.reflection, 0u);
    EXPECT_GT(stats.rays.refraction, 0u);
  }
}

TEST(RenderImage, CornerSamplingIsTheMeanOfFourCornerRays) {
  const nff::Scene scene = spheres_scene();  // 40 x 30: not square
  const World world = build_world(scene);
  const Camera camera = make_camera(scene.view);
  RenderStats stats;
  const Image image = render(world, camera, {Accel::none, Sampling::corners, 5}, stats);
  EXPECT_EQ(stats.rays.eye, 41u * 31u);

  RayCounts rays;
  TestCounters tests;
  Tracer tracer(world, {Accel::none, 5}, rays, tests);
  auto corner = [&](int x, int y) {
    const Ray r = camera.ray_at(x, y);
    return tracer.trace_eye(r, camera.t_min(r));
  };
  for (int j = 0; j < camera.height; j += 3) {
    for (int i = 0; i < camera.width; i += 3) {
      const Vec3 mean =
          (corner(i, j) + corner(i + 1, j) + corner(i, j + 1) + corner(i + 1, j + 1)) * 0.25;
      const Vec3 pixel = image.at(i, j);
      EXPECT_NEAR(pixel.x, mean.x, 1e-6);
      EXPECT_NEAR(pixel.y, mean.y, 1e-6);
      EXPECT_NEAR(pixel.z, mean.z, 1e-6);
    }
  }
}

TEST(RenderImage, CentreSamplingCastsOneEyeRayPerPixel) {
  RenderStats stats;
  render_scene(spheres_scene(), stats, {});
  EXPECT_EQ(stats.rays.eye, 40u * 30u);
  EXPECT_EQ(stats.rays.eye_hits, 40u * 30u);  // the floor fills the view
}

TEST(RenderImage, RenderingTwiceGivesTheSameBits) {
  for (const nff::Scene& scene : {spheres_scene(), patches_scene()}) {
    RenderStats first_stats;
    RenderStats second_stats;
    const Image first = render_scene(scene, first_stats, {});
    const Image second = render_scene(scene, second_stats, {});
    EXPECT_EQ(first.rgb, second.rgb);
    EXPECT_EQ(first_stats.tests.primitive_tests, second_stats.tests.primitive_tests);
  }
}

TEST(RenderImage, HitherClipsNearGeometry) {
  nff::Scene scene = test::make_scene({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 30, 9, 9);
  add_polygon(scene, test::square_z(-5, -5, 5, 5, 8), add_material(scene, {{1, 0, 0}}));
  add_polygon(scene, test::square_z(-5, -5, 5, 5, 0), add_material(scene, {{0, 1, 0}}));
  scene.view.hither = 3.0;
  RenderStats stats;
  const Image image = render_scene(scene, stats, {});
  EXPECT_NEAR(image.at(4, 4).y, 0.1, 1e-7);  // the far green square, not the near red one
  EXPECT_EQ(image.at(4, 4).x, 0.0);
}

}  // namespace
}  // namespace raygate::render

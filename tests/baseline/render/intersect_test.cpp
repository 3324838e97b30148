// Exact primitive tests: analytic hit distances and normals, both sides, no caps, concave
// outlines, and the bbox test never rejecting a ray the exact test accepts.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "render/intersect.h"
#include "render/surface.h"
#include "render/world.h"
#include "scene_builder.h"

namespace raygate::render {
namespace {

using test::add_cone;
using test::add_material;
using test::add_patch;
using test::add_polygon;
using test::add_sphere;

constexpr double kInf = std::numeric_limits<double>::infinity();

nff::Scene blank() { return test::make_scene({0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 45, 8, 8); }

Ray ray(Vec3 origin, Vec3 direction) { return {origin, normalize(direction)}; }

bool nearest(const World& world, const Ray& r, Hit& hit) {
  TestCounters counters;
  return find_nearest(world, Accel::none, r, 0.0, kInf, hit, counters);
}

void expect_vec_near(const Vec3& a, const Vec3& b, double tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

TEST(SphereIntersect, HitsNearSideFromOutsideAndFarSideFromInside) {
  nff::Scene scene = blank();
  add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, {}));
  const World world = build_world(scene);
  Hit hit;
  ASSERT_TRUE(nearest(world, ray({0, 0, -5}, {0, 0, 1}), hit));
  EXPECT_DOUBLE_EQ(hit.t, 4.0);
  ASSERT_TRUE(nearest(world, ray({0, 0, 0}, {0, 0, 1}), hit));
  EXPECT_DOUBLE_EQ(hit.t, 1.0);
  EXPECT_FALSE(nearest(world, ray({0, 0, -5}, {0, 0, -1}), hit));         // behind the origin
  EXPECT_FALSE(nearest(world, ray({0, 1.0000001, -5}, {0, 0, 1}), hit));  // just outside
}

TEST(SphereIntersect, StaysAccurateFromADistantOrigin) {
  nff::Scene scene = blank();
  add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, {}));
  const World world = build_world(scene);
  Hit hit;
  ASSERT_TRUE(nearest(world, ray({0, 0.5, -1e7}, {0, 0, 1}), hit));
  const SurfacePoint s = evaluate_surface(world, ray({0, 0.5, -1e7}, {0, 0, 1}), hit);
  // Along the surface the hit is as good as t (ulp(1e7) ~ 2e-9); across it, exact.
  EXPECT_NEAR(s.point.z, -std::sqrt(0.75), 1e-8);
  EXPECT_NEAR(length(s.point), 1.0, 1e-15);
}

TEST(SphereIntersect, NegativeRadiusTurnsTheGeometricNormalInward) {
  nff::Scene scene = blank();
  add_sphere(scene, {0, 0, 0}, -1.0, add_material(scene, {}));
  const World world = build_world(scene);
  Hit hit;
  const Ray r = ray({0, 0, -5}, {0, 0, 1});
  ASSERT_TRUE(nearest(world, r, hit));
  expect_vec_near(evaluate_surface(world, r, hit).geometric_normal, {0, 0, 1}, 1e-15);
}

TEST(ConeIntersect, OpenCylinderFromOutsideInsideAndAlongTheAxis) {
  nff::Scene scene = blank();
  add_cone(scene, {0, 0, 0}, 1.0, {0, 0, 2}, 1.0, add_material(scene, {}));
  const World world = build_world(scene);
  Hit hit;
  const Ray from_side = ray({-5, 0, 1}, {1, 0, 0});
  ASSERT_TRUE(nearest(world, from_side, hit));
  EXPECT_NEAR(hit.t, 4.0, 1e-12);
  expect_vec_near(evaluate_surface(world, from_side, hit).geometric_normal, {-1, 0, 0}, 1e-12);
  ASSERT_TRUE(nearest(world, ray({0, 0, 1}, {1, 0, 0}), hit));
  EXPECT_NEAR(hit.t, 1.0, 1e-12);
  EXPECT_FALSE(nearest(world, ray({-5, 0, 2.5}, {1, 0, 0}), hit));  // above: no cap
  EXPECT_FALSE(nearest(world, ray({0, 0, 5}, {0, 0, -1}), hit));    // down the open tube
  // Slanted through the top opening: meets the inside wall, not a cap.
  ASSERT_TRUE(nearest(world, ray({0, 0, 3}, {1, 0, -1}), hit));
  EXPECT_NEAR(hit.t, std::sqrt(2.0), 1e-12);
}

TEST(ConeIntersect, ConeWithApexPointHasSlantedNormal) {
  nff::Scene scene = blank();
  add_cone(scene, {0, 0, 0}, 1.0, {0, 0, 1}, 0.0, add_material(scene, {}));
  const World world = build_world(scene);
  Hit hit;
  const Ray r = ray({-5, 0, 0.5}, {1, 0, 0});
  ASSERT_TRUE(nearest(world, r, hit));
  EXPECT_NEAR(hit.t, 4.5, 1e-12);
  const SurfacePoint s = evaluate_surface(world, r, hit);
  expect_vec_near(s.point, {-0.5, 0, 0.5}, 1e-12);
  expect_vec_near(s.geometric_normal, normalize(Vec3{-1, 0, 1}), 1e-12);
  EXPECT_FALSE(nearest(world, ray({-5, 0, 1.2}, {1, 0, 0}), hit));  // no mirrored nappe
}

TEST(ConeIntersect, ZeroBaseRadiusAndRayParallelToASideLine) {
  nff::Scene scene = blank();
  add_cone(scene, {0, 0, 0}, 0.0, {0, 0, 1}, 1.0, add_material(scene, {}));
  const World world = build_world(scene);
  Hit hit;
  ASSERT_TRUE(nearest(world, ray({-5, 0, 0.5}, {1, 0, 0}), hit));
  EXPECT_NEAR(hit.t, 4.5, 1e-12);
  // Parallel to the side line x = z (A = 0): the single linear root, on the far side.
  ASSERT_TRUE(nearest(world, ray({-0.5, 0, 0.0}, {1, 0, 1}), hit));
  const Vec3 p = point_at(ray({-0.5, 0, 0.0}, {1, 0, 1}), hit.t);
  EXPECT_NEAR(std::hypot(p.x, p.y), p.z, 1e-12);
}

// A concave "U": the ray through the notch misses, rays through the arms hit from either side.
TEST(PolygonIntersect, ConcaveOutlineByEvenOddRule) {
  nff::Scene scene = blank();
  add_polygon(
      scene,
      {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {2, 3, 0}, {2, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}},
      add_material(scene, {}));
  const World world = build_world(scene);
  Hit hit;
  EXPECT_FALSE(nearest(world, ray({1.5, 2, 5}, {0, 0, -1}), hit));  // the notch
  ASSERT_TRUE(nearest(world, ray({0.5, 2, 5}, {0, 0, -1}), hit));
  EXPECT_DOUBLE_EQ(hit.t, 5.0);
  ASSERT_TRUE(nearest(world, ray({2.5, 2, -5}, {0, 0, 1}), hit));  // from the back
  EXPECT_DOUBLE_EQ(hit.t, 5.0);
  EXPECT_FALSE(nearest(world, ray({3.5, 2, 5}, {0, 0, -1}), hit));
  EXPECT_FALSE(nearest(world, ray({-1, 2, 1}, {1, 0, 0}), hit));  // in the plane
}

TEST(PolygonIntersect, NormalFollowsCounterClockwiseWinding) {
  nff::Scene scene = blank();
  add_polygon(scene, test::square_z(0, 0, 1, 1, 0), add_material(scene, {}));
  const World world = build_world(scene);
  expect_vec_near(world.polygons[0].normal, {0, 0, 1}, 0);
}

TEST(TriangleIntersect, SmoothNormalIsTheNormalizedBarycentricBlend) {
  nff::Scene scene = blank();
  const std::vector<Vec3> normals = {
      normalize(Vec3{-1, 0, 1}), normalize(Vec3{1, 0, 1}), {0, 0, 1}};
  add_patch(scene, {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}}, normals, add_material(scene, {}));
  const World world = build_world(scene);
  Hit hit;
  const Ray r = ray({0.5, 0.5, 3}, {0, 0, -1});
  ASSERT_TRUE(nearest(world, r, hit));
  EXPECT_DOUBLE_EQ(hit.t, 3.0);
  EXPECT_DOUBLE_EQ(hit.b1, 0.25);
  EXPECT_DOUBLE_EQ(hit.b2, 0.25);
  const SurfacePoint s = evaluate_surface(world, r, hit);
  expect_vec_near(s.shading_normal,
                  normalize(normals[0] * 0.5 + normals[1] * 0.25 + normals[2] * 0.25), 1e-15);
  expect_vec_near(s.geometric_normal, {0, 0, 1}, 0);
}

TEST(TriangleIntersect, PatchWithMoreThanThreeVerticesIsTriangulated) {
  nff::Scene scene = blank();
  const Vec3 up{0, 0, 1};
  add_patch(scene, {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 0.5, 0}, {0, 2, 0}}, {up, up, up, up, up},
            add_material(scene, {}));
  const World world = build_world(scene);
  EXPECT_EQ(world.triangles.size(), 3u);
  Hit hit;
  EXPECT_TRUE(nearest(world, ray({1.9, 1.5, 1}, {0, 0, -1}), hit));
  EXPECT_TRUE(nearest(world, ray({0.1, 1.5, 1}, {0, 0, -1}), hit));
  EXPECT_FALSE(nearest(world, ray({1.0, 1.5, 1}, {0, 0, -1}), hit));  // the concave notch
}

TEST(WorldBuild, DegeneratePrimitivesAreDroppedAndCounted) {
  nff::Scene scene = blank();
  const int m = add_material(scene, {});
  add_sphere(scene, {0, 0, 0}, 0.0, m);
  add_cone(scene, {0, 0, 0}, 1.0, {0, 0, 0}, 1.0, m);
  add_polygon(scene, {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, m);
  const World world = build_world(scene);
  EXPECT_EQ(world.primitive_count(), 0u);
  EXPECT_EQ(world.degenerate_primitives, 3u);
}

TEST(WorldBuild, BadMaterialIndexIsASceneError) {
  nff::Scene scene = blank();
  add_sphere(scene, {0, 0, 0}, 1.0, 3);
  EXPECT_THROW(build_world(scene), SceneError);
}

// Rays aimed at random points on each primitive, including its silhouette (grazing): whenever
// the exact test hits, the padded box must be hit over the same interval.
TEST(BoxTest, NeverRejectsAnExactHit) {
  nff::Scene scene = blank();
  const int m = add_material(scene, {});
  add_sphere(scene, {0.3, -0.2, 0.1}, 0.7, m);
  add_cone(scene, {1, 1, 0}, 0.5, {1.5, 1.2, 1}, 0.1, m);
  add_polygon(scene, {{-1, -1, -1}, {0, -1, -0.5}, {-0.5, 0, -0.2}}, m);
  add_patch(scene, {{2, 0, 0}, {3, 0, 1}, {2, 1, 0}}, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, m);
  const World world = build_world(scene);
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int exact_hits = 0;
  for (int i = 0; i < 200000; ++i) {
    const Vec3 origin{unit(rng) * 6, unit(rng) * 6, unit(rng) * 6};
    const Vec3 target{unit(rng) * 2 + 1, unit(rng) * 1.5, unit(rng) * 1.5};
    const Ray r{origin, normalize(target - origin)};
    const SlabRay slab = make_slab_ray(r);
    PrimHit h;
    auto check = [&](bool hit, const Aabb& box) {
      if (!hit) return;
      ++exact_hits;
      EXPECT_TRUE(hits_box(box, slab, 0.0, h.t * (1 + 1e-15) + 1e-300)) << i;
    };
    check(intersect(world.spheres[0], r, 0.0, kInf, h), world.sphere_boxes[0]);
    check(intersect(world.cones[0], r, 0.0, kInf, h), world.cone_boxes[0]);
    check(intersect(world.polygons[0], world.polygon_points, r, 0.0, kInf, h),
          world.polygon_boxes[0]);
    check(intersect(world.triangles[0], r, 0.0, kInf, h), world.triangle_boxes[0]);
  }
  EXPECT_GT(exact_hits, 10000);
}

TEST(BoxTest, AxisParallelRaysUseTheOriginTest) {
  const Aabb box{{0, 0, 0}, {1, 1, 1}};
  EXPECT_TRUE(hits_box(box, make_slab_ray(ray({0.5, 0.5, -1}, {0, 0, 1})), 0.0, kInf));
  EXPECT_FALSE(hits_box(box, make_slab_ray(ray({1.5, 0.5, -1}, {0, 0, 1})), 0.0, kInf));
  EXPECT_TRUE(hits_box(box, make_slab_ray(ray({0.0, 0.0, -1}, {0, 0, 1})), 0.0, kInf));
  EXPECT_FALSE(hits_box(box, make_slab_ray(ray({0.5, 0.5, -1}, {0, 0, 1})), 0.0, 0.5));
}

}  // namespace
}  // namespace raygate::render

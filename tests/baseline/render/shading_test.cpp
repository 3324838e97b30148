// Whitted shading against values derived by hand: ambient + diffuse + highlight with the
// 1/sqrt(n) light convention, a mirror, Snell through a slab and a sphere, total internal
// reflection, a sharp shadow edge, two-sidedness, and no acne or light leaks.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

#include "render/render.h"
#include "render/surface.h"
#include "render/tracer.h"
#include "scene_builder.h"

namespace raygate::render {
namespace {

using test::add_light;
using test::add_material;
using test::add_polygon;
using test::add_sphere;
using test::MaterialSpec;

constexpr double kInf = std::numeric_limits<double>::infinity();

Image render_scene(const nff::Scene& scene, RenderStats& stats, const RenderOptions& options = {}) {
  return render(build_world(scene), make_camera(scene.view), options, stats);
}

void expect_color_near(const Vec3& actual, const Vec3& expected, double tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(actual.z, expected.z, tolerance);
}

constexpr double kFloatTolerance = 1e-6;  // images hold floats

// Camera on +z looking down at the origin; 33x33 so pixel (16, 16) looks straight down.
nff::Scene looking_down(double height, Vec3 background = {}) {
  return test::make_scene({0, 0, height}, {0, 0, 0}, {0, 1, 0}, 30, 33, 33, background);
}

TEST(Shading, LitDiffuseSphereCentreIsAmbientPlusDiffuse) {
  nff::Scene scene = looking_down(10);
  const Vec3 color{0.8, 0.5, 0.2};
  add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, {color, 0.7}));
  add_light(scene, {0, 0, 10});
  RenderStats stats;
  const Image image = render_scene(scene, stats);
  expect_color_near(image.at(16, 16), color * (kAmbient + 0.7), kFloatTolerance);
}

TEST(Shading, EachOfNLightsHasIntensityOneOverSqrtN) {
  nff::Scene scene = looking_down(10);
  const Vec3 color{0.8, 0.5, 0.2};
  add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, {color, 0.7}));
  add_light(scene, {0, 0, 10});
  add_light(scene, {0, 0, 20});
  RenderStats stats;
  const Image image = render_scene(scene, stats);
  expect_color_near(image.at(16, 16), color * (kAmbient + 2.0 * 0.7 / std::sqrt(2.0)),
                    kFloatTolerance);
}

TEST(Shading, HighlightAddsKsAtTheMirrorDirection) {
  nff::Scene scene = looking_down(10);
  const Vec3 color{0.8, 0.5, 0.2};
  add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, {color, 0.6, 0.3, 20.0}));
  add_light(scene, {0, 0, 10});
  RenderStats stats;
  const Image image = render_scene(scene, stats);
  // The reflection ray goes back up and sees the black background.
  expect_color_near(image.at(16, 16), color * (kAmbient + 0.6) + Vec3{0.3, 0.3, 0.3},
                    kFloatTolerance);
}

// A black mirror facing the eye reflects the eye ray straight back, past the eye, onto a
// sphere behind the camera that eye rays never see.
TEST(Shading, MirrorShowsWhatIsBehindTheCamera) {
  const Vec3 background{0.3, 0.2, 0.1};
  nff::Scene scene = looking_down(10, background);
  add_polygon(scene, test::square_z(-1, -1, 1, 1, 0), add_material(scene, {{0, 0, 0}, 0, 1}));
  const Vec3 sphere_color{0.2, 0.9, 0.4};
  add_sphere(scene, {0, 0, 20}, 2.0, add_material(scene, {sphere_color}));
  RenderStats stats;
  const Image image = render_scene(scene, stats);
  expect_color_near(image.at(16, 16), sphere_color * kAmbient, kFloatTolerance);
  expect_color_near(image.at(0, 0), background, kFloatTolerance);  // beside the mirror
}

// A floor at z = 0, a square occluder |x|,|y| <= 1 at z = 5, a light at (0, 0, 10): the shadow
// is |x|,|y| <= 2. The camera at z = 20 sees the floor over |x| <= 4 across 100 pixels, so
// column 74's centre lands at x = 1.96 (shadow) and column 75's at x = 2.04 (lit); the
// occluder itself hides only |x| < 4/3.
TEST(Shading, SharpShadowEdgeFromAPolygon) {
  nff::Scene scene = test::make_scene({0, 0, 20}, {0, 0, 0}, {0, 1, 0},
                                      2.0 * std::atan(0.2) * 180.0 / std::numbers::pi, 100, 100);
  const Vec3 floor_color{0.9, 0.8, 0.7};
  add_polygon(scene, test::square_z(-10, -10, 10, 10, 0), add_material(scene, {floor_color, 1}));
  add_polygon(scene, test::square_z(-1, -1, 1, 1, 5), add_material(scene, {{1, 1, 1}, 1}));
  add_light(scene, {0, 0, 10});
  RenderStats stats;
  const Image image = render_scene(scene, stats);
  const int row = 50;  // y = -0.04
  expect_color_near(image.at(74, row), floor_color * kAmbient, kFloatTolerance);
  const Vec3 lit_point{2.04, -0.04, 0};
  const double n_dot_l = normalize(Vec3{0, 0, 10} - lit_point).z;
  expect_color_near(image.at(75, row), floor_color * (kAmbient + n_dot_l), kFloatTolerance);
}

TEST(Shading, PolygonsAreLitFromTheirBackSide) {
  nff::Scene scene = looking_down(10);
  // Clockwise seen from the eye: the eye sees its back.
  add_polygon(scene, {{-1, -1, 0}, {-1, 1, 0}, {1, 1, 0}, {1, -1, 0}},
              add_material(scene, {{1, 1, 1}, 0.5}));
  add_light(scene, {0, 0, 10});
  RenderStats stats;
  const Image image = render_scene(scene, stats);
  expect_color_near(image.at(16, 16), Vec3{1, 1, 1} * (kAmbient + 0.5), kFloatTolerance);
}

TEST(Shading, NoShadowRayTowardALightBehindTheSurface) {
  nff::Scene scene = looking_down(10);
  add_polygon(scene, test::square_z(-5, -5, 5, 5, 0), add_material(scene, {{1, 1, 1}, 0.5}));
  add_light(scene, {0, 0, -3});
  RenderStats stats;
  const Image image = render_scene(scene, stats);
  EXPECT_EQ(stats.rays.shadow, 0u);
  expect_color_near(image.at(16, 16), Vec3{1, 1, 1} * kAmbient, kFloatTolerance);
}

// Every visible point of a sphere lit from the eye must get exactly its analytic diffuse
// term: a single self-shadowed pixel (acne) fails.
TEST(Shading, NoShadowAcneOnALitSphere) {
  nff::Scene scene = test::make_scene({0, 0, 4}, {0, 0, 0}, {0, 1, 0}, 40, 64, 64);
  add_sphere(scene, {0.1, 0.05, 0}, 1.0, add_material(scene, {{1, 1, 1}, 1}));
  add_light(scene, {0, 0, 4});
  RenderStats stats;
  const Image image = render_scene(scene, stats);
  const Camera camera = make_camera(scene.view);
  int sphere_pixels = 0;
  for (int j = 0; j < 64; ++j) {
    for (int i = 0; i < 64; ++i) {
      const Ray r = camera.ray_at(i + 0.5, j + 0.5);
      const Vec3 oc = r.origin - Vec3{0.1, 0.05, 0};
      const double b = dot(oc, r.direction);
      const double h = b * b - (dot(oc, oc) - 1.0);
      if (h < 1e-6) continue;  // miss, or too close to the silhouette to compute here
      const Vec3 p = point_at(r, -b - std::sqrt(h));
      const Vec3 n = p - Vec3{0.1, 0.05, 0};
      const double n_dot_l = dot(n, normalize(Vec3{0, 0, 4} - p));
      ++sphere_pixels;
      EXPECT_NEAR(image.at(i, j).x, kAmbient + n_dot_l, 1e-5) << i << "," << j;
    }
  }
  EXPECT_GT(sphere_pixels, 500);
}

// The eye inside a closed cube of six two-sided polygons, the light outside: nothing leaks in.
TEST(Shading, NoLightLeaksIntoAClosedBox) {
  nff::Scene scene = test::make_scene({0.2, 0.1, 0.3}, {1, 0.7, -1}, {0, 0, 1}, 120, 64, 64);
  const int m = add_material(scene, {{1, 1, 1}, 1});
  const double s = 1.0;
  add_polygon(scene, {{-s, -s, -s}, {s, -s, -s}, {s, s, -s}, {-s, s, -s}}, m);
  add_polygon(scene, {{-s, -s, s}, {s, -s, s}, {s, s, s}, {-s, s, s}}, m);
  add_polygon(scene, {{-s, -s, -s}, {s, -s, -s}, {s, -s, s}, {-s, -s, s}}, m);
  add_polygon(scene, {{-s, s, -s}, {s, s, -s}, {s, s, s}, {-s, s, s}}, m);
  add_polygon(scene, {{-s, -s, -s}, {-s, s, -s}, {-s, s, s}, {-s, -s, s}}, m);
  add_polygon(scene, {{s, -s, -s}, {s, s, -s}, {s, s, s}, {s, -s, s}}, m);
  add_light(scene, {0.3, 0.2, 5});
  RenderStats stats;
  const Image image = render_scene(scene, stats);
  EXPECT_GT(stats.rays.shadow, 0u);  // the top face's inside looks away; others cast rays
  for (int j = 0; j < 64; ++j) {
    for (int i = 0; i < 64; ++i) {
      expect_color_near(image.at(i, j), Vec3{1, 1, 1} * kAmbient, kFloatTolerance);
    }
  }
}

// --- Refraction, followed ray by ray with the tracer's own spawn_secondary -----------------
// Secondary rays start 1e-9 (relative) off the surface, so positions after a refraction agree
// with the analytic ones to about that.
constexpr double kOffsetTolerance = 1e-8;

struct Traced {
  SurfacePoint surface;
  SecondaryRays next;
};

Traced hit_and_spawn(const World& world, const Ray& r) {
  TestCounters counters;
  Hit hit;
  EXPECT_TRUE(find_nearest(world, Accel::none, r, 0.0, kInf, hit, counters));
  Traced out;
  out.surface = evaluate_surface(world, r, hit);
  out.next = spawn_secondary(r, out.surface, world.materials[out.surface.material]);
  return out;
}

const MaterialSpec kGlass{{1, 1, 1}, 0.0, 0.0, 1.0, 1.0, 1.5};

// A ray entering a glass sphere at 30 degrees bends per Snell, meets the far side of the same
// sphere after the chord 2 r cos(theta_t), and leaves at 30 degrees again.
TEST(Refraction, SphereBendsPerSnellAndFindsItsFarSide) {
  nff::Scene scene = looking_down(10);
  add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, kGlass));
  const World world = build_world(scene);
  const double theta_i = 30.0 * std::numbers::pi / 180.0;
  const Ray in{{std::sin(theta_i), 0, 5}, {0, 0, -1}};  // meets the surface at 30 degrees
  const Traced first = hit_and_spawn(world, in);
  ASSERT_TRUE(first.next.refracts);
  const double sin_t = std::sin(theta_i) / 1.5;
  const Vec3 n = first.surface.geometric_normal;
  EXPECT_NEAR(length(cross(first.next.refracted.direction, -n)), sin_t, 1e-14);
  EXPECT_NEAR(first.next.refracted.direction.y, 0.0, 1e-15);  // stays in the plane of incidence
  EXPECT_LT(first.next.refracted.direction.x, 0.0);           // bent toward the normal

  const Traced second = hit_and_spawn(world, first.next.refracted);
  const double chord = 2.0 * std::cos(std::asin(sin_t));
  const Vec3 expected_exit = first.surface.point + first.next.refracted.direction * chord;
  EXPECT_NEAR(length(second.surface.point - expected_exit), 0.0, kOffsetTolerance);
  ASSERT_TRUE(second.next.refracts);
  const double cos_out = dot(second.next.refracted.direction, second.surface.geometric_normal);
  EXPECT_NEAR(cos_out, std::cos(theta_i), kOffsetTolerance);
}

// A slab of thickness 1 between z = 0 and z = -1: the ray leaves parallel to how it came,
// shifted sideways by t sin(theta_i - theta_t) / cos(theta_t).
TEST(Refraction, SlabDisplacesARayWithoutTurningIt) {
  nff::Scene scene = looking_down(10);
  const int glass = add_material(scene, kGlass);
  add_polygon(scene, test::square_z(-5, -5, 5, 5, 0), glass);
  // The bottom face's front looks down (clockwise seen from above): entering and leaving are
  // decided by geometric normals, so a closed solid's faces must all face outward.
  add_polygon(scene, {{-5, -5, -1}, {-5, 5, -1}, {5, 5, -1}, {5, -5, -1}}, glass);
  const World world = build_world(scene);
  const double theta_i = 40.0 * std::numbers::pi / 180.0;
  const Ray in{{-std::tan(theta_i), 0, 1}, {std::sin(theta_i), 0, -std::cos(theta_i)}};
  const Traced top = hit_and_spawn(world, in);
  ASSERT_TRUE(top.next.refracts);
  const Traced bottom = hit_and_spawn(world, top.next.refracted);
  ASSERT_TRUE(bottom.next.refracts);
  const Vec3 out = bottom.next.refracted.direction;
  EXPECT_NEAR(out.x, in.direction.x, 1e-15);
  EXPECT_NEAR(out.z, in.direction.z, 1e-15);
  const double theta_t = std::asin(std::sin(theta_i) / 1.5);
  EXPECT_NEAR(bottom.surface.point.x, std::tan(theta_t), kOffsetTolerance);
  EXPECT_NEAR(bottom.surface.point.z, -1.0, 1e-15);
  // Perpendicular distance between the incoming line and the outgoing one.
  const double shift = std::sin(theta_i - theta_t) / std::cos(theta_t);
  const Vec3 offset = bottom.surface.point - point_at(in, 1.0 / std::cos(theta_i));
  EXPECT_NEAR(length(offset - in.direction * dot(offset, in.direction)), shift, kOffsetTolerance);
}

// Leaving glass (ior 1.5) the critical angle is asin(1/1.5) = 41.81 degrees.
TEST(Refraction, TotalInternalReflectionAboveTheCriticalAngle) {
  nff::Scene scene = looking_down(10);
  add_polygon(scene, test::square_z(-5, -5, 5, 5, 0), add_material(scene, kGlass));
  const World world = build_world(scene);
  const double critical = std::asin(1.0 / 1.5);
  for (const double delta : {-1e-6, 1e-6}) {
    const double theta = critical + delta;
    const Ray up_from_inside{{0, 0, -1}, {std::sin(theta), 0, std::cos(theta)}};
    const Traced t = hit_and_spawn(world, up_from_inside);
    EXPECT_EQ(t.next.refracts, delta < 0) << delta;
    EXPECT_TRUE(t.next.reflects);
    EXPECT_DOUBLE_EQ(t.next.reflection_weight, delta < 0 ? 0.0 : 1.0);  // Ks + T on TIR
    EXPECT_LT(t.next.reflected.direction.z, 0.0);
  }
}

// Inside a glass sphere (Ks = 0, T = 1, colour C) a ray meets the surface at 60 degrees: TIR
// sends all of T into the reflected ray, so with depth 2 the colour is 0.1 C (this hit)
// + 1 * 0.1 C (the next hit inside), and no refraction ray is counted. At 30 degrees the ray
// leaves instead and sees the background.
TEST(Refraction, TirEnergyGoesToTheReflectedRay) {
  const Vec3 background{0.0, 0.25, 0.5};
  nff::Scene scene = looking_down(10, background);
  const Vec3 color{0.4, 0.6, 0.8};
  MaterialSpec glass = kGlass;
  glass.color = color;
  add_sphere(scene, {0, 0, 0}, 1.0, add_material(scene, glass));
  const World world = build_world(scene);
  for (const double degrees : {60.0, 30.0}) {
    const double theta = degrees * std::numbers::pi / 180.0;
    // From the chord's midpoint, so the surface is met at `theta` from the normal.
    const Vec3 start{std::sin(theta), 0, 0};
    RayCounts rays;
    TestCounters tests;
    Tracer tracer(world, {Accel::none, 2}, rays, tests);
    const Vec3 c = tracer.trace({start, {0, 1, 0}}, 0.0, 1);
    EXPECT_EQ(rays.reflection, 1u);
    if (degrees == 60.0) {
      EXPECT_EQ(rays.refraction, 0u);
      EXPECT_EQ(rays.total_internal_reflections, 1u);
      expect_color_near(c, color * (2.0 * kAmbient), 1e-15);
    } else {
      EXPECT_EQ(rays.refraction, 1u);
      EXPECT_EQ(rays.total_internal_reflections, 0u);
      expect_color_near(c, color * kAmbient + background, 1e-15);
    }
  }
}

TEST(Depth, EyeRayIsDepthOneAndTheLimitStopsSpawning) {
  nff::Scene scene = looking_down(10);
  // Two parallel mirrors: every hit would spawn a reflection without a depth limit.
  const int mirror = add_material(scene, {{1, 1, 1}, 0, 1});
  add_polygon(scene, test::square_z(-50, -50, 50, 50, 0), mirror);
  add_polygon(scene, test::square_z(-50, -50, 50, 50, 20), mirror);
  const World world = build_world(scene);
  for (const int depth : {1, 2, 5}) {
    RayCounts rays;
    TestCounters tests;
    Tracer tracer(world, {Accel::none, depth}, rays, tests);
    tracer.trace_eye({{0, 0, 10}, {0, 0, -1}}, 0.0);
    EXPECT_EQ(rays.eye, 1u);
    EXPECT_EQ(rays.reflection, std::uint64_t(depth - 1)) << depth;
  }
}

}  // namespace
}  // namespace raygate::render

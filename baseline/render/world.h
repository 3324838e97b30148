// The scene as the tracer sees it: primitives prepared once, their padded boxes, shading
// materials and lights; and the two ray queries (nearest hit, any occluder) in both
// acceleration modes. Primitive order is kind by kind (spheres, cones, polygons, patch
// triangles), each in file order; nearest-hit ties go to the lowest index in that order.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "geom/aabb.h"
#include "geom/ray.h"
#include "nff/scene.h"
#include "render/primitives.h"

namespace raygate::render {

enum class Accel { none, bbox };

enum class PrimKind : std::uint8_t { sphere, cone, polygon, triangle };

struct Hit {
  double t = 0.0;
  PrimKind kind = PrimKind::sphere;
  int index = 0;    // within its kind's array
  double b1 = 0.0;  // triangle barycentrics (weights of vertices 1 and 2)
  double b2 = 0.0;
};

// Work counters. Incremented per test, so they cost the same in both modes.
struct TestCounters {
  std::uint64_t primitive_tests = 0;
  std::uint64_t bbox_tests = 0;
};

// An NFF material made ready for shading (see docs/baseline.md for the clamps).
struct ShadingMaterial {
  Vec3 color;
  double kd = 0.0;
  double ks = 0.0;
  double shine = 1.0;  // Phong exponent, at least 1 (as SPD's readnff clamps)
  double transmittance = 0.0;
  double ior = 1.0;  // 1 when the file gives a non-positive or non-finite value
};

struct PointLight {
  Vec3 position;
  Vec3 intensity;  // colour / sqrt(light count)
};

struct World {
  std::vector<SpherePrim> spheres;
  std::vector<ConePrim> cones;
  std::vector<PolygonPrim> polygons;
  std::vector<Point2> polygon_points;
  std::vector<TrianglePrim> triangles;
  // Padded boxes, parallel to the arrays above.
  std::vector<Aabb> sphere_boxes;
  std::vector<Aabb> cone_boxes;
  std::vector<Aabb> polygon_boxes;
  std::vector<Aabb> triangle_boxes;

  std::vector<ShadingMaterial> materials;
  std::vector<PointLight> lights;
  Vec3 background;
  std::size_t degenerate_primitives = 0;  // dropped at build time: no ray can hit them

  std::size_t primitive_count() const {
    return spheres.size() + cones.size() + polygons.size() + triangles.size();
  }
};

// Relative padding of the per-primitive boxes: far above the error of any hit point, so the
// box test never rejects a primitive the exact test would accept.
inline constexpr double kBoxPaddingRelative = 1e-6;

// A scene the tracer cannot use (bad material index, degenerate view): usage-level error.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws SceneError if a primitive refers to a material that does not exist.
World build_world(const nff::Scene& scene);

// Nearest hit with t_min < t < t_max; false if none.
bool find_nearest(const World& world, Accel accel, const Ray& ray, double t_min, double t_max,
                  Hit& hit, TestCounters& counters);

// Any primitive with 0 < t < t_max; stops at the first one found.
bool is_occluded(const World& world, Accel accel, const Ray& ray, double t_max,
                 TestCounters& counters);

}  // namespace raygate::render

// SPD "balls" (sphereflake), spd-spec.md §3.1: a fractal of spheres, each sprouting 9 children
// of 1/3 its radius that touch it, above a square floor; 3 lights.
#include <array>
#include <cmath>
#include <numbers>

#include "generators/generators.h"
#include "lib/matrix.h"

namespace raygate::scenes {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kChildRatio = 1.0 / 3.0;
// §3.1 (2021 version): directions this close to ±Z take the special-case branches.
constexpr double kAxisTolerance = 0.9999;

using ObjectSet = std::array<Vec3, 9>;

// The 9 unit child directions for a parent pointing along +Z (§3.1 "objset"): a trio tilted
// by Rot(normalize(1,-1,0), asin(2/√6)), then copied three times around Z by 120°.
ObjectSet make_object_set() {
  const double d = 1.0 / std::sqrt(2.0);
  std::array<Vec3, 3> trio{{{d, d, 0.0}, {d, 0.0, -d}, {0.0, d, -d}}};
  const Matrix4 tilt =
      Matrix4::rotate_axis(normalize(Vec3{1.0, -1.0, 0.0}), std::asin(2.0 / std::sqrt(6.0)));
  for (Vec3& v : trio) v = transform_vector(v, tilt);

  ObjectSet set;
  for (int s = 0; s < 3; ++s) {
    const Matrix4 spin = Matrix4::rotate_z(s * 2.0 * kPi / 3.0);
    for (int v = 0; v < 3; ++v) set[3 * s + v] = transform_vector(trio[v], spin);
  }
  return set;
}

// The rotation taking +Z to the unit direction d (§3.1 recursion step 2).
Matrix4 orient_to(const Vec3& d) {
  if (d.z >= kAxisTolerance) return Matrix4::identity();
  if (d.z <= -kAxisTolerance) return Matrix4::rotate_y(kPi);
  return Matrix4::rotate_axis(normalize(cross(Vec3{0.0, 0.0, 1.0}, d)), std::acos(d.z));
}

// Depth-first pre-order: the sphere, then its 9 children (§3.1 "Recursion").
void emit_node(int depth, const Vec3& center, double radius, const Vec3& direction,
               const ObjectSet& set, NffWriter& out) {
  out.sphere(center, radius);
  if (depth <= 0) return;
  const Matrix4 m = orient_to(direction);
  const double scale = radius * (1.0 + kChildRatio);
  for (const Vec3& o : set) {
    const Vec3 child = transform_vector(o, m) * scale + center;
    // The child's direction is recovered from its centre, not taken from o·M: the rounding
    // difference decides the ±0.9999 tests at depth (§3.1).
    const Vec3 child_dir = (child - center) / scale;
    emit_node(depth - 1, child, radius * kChildRatio, child_dir, set, out);
  }
}

}  // namespace

void generate_balls(int size, NffWriter& out) {
  out.background({0.078, 0.361, 0.753});
  out.view({2.1, 1.3, 1.7}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 45.0, 0.01, 512, 512);
  out.light({4.0, 3.0, 2.0});
  out.light({1.0, -4.0, 4.0});
  out.light({-3.0, 1.0, 5.0});

  // Floor: enclosing radius 1, at z = -radius/2, spanning ±12·radius, facing +z.
  out.material({{1.0, 0.75, 0.33}, 0.2, 0.8, 0.0, 0.0, 0.0, 0.0, 1.0});
  const std::array<Vec3, 4> floor{
      {{12.0, 12.0, -0.5}, {-12.0, 12.0, -0.5}, {-12.0, -12.0, -0.5}, {12.0, -12.0, -0.5}}};
  out.polygon(floor);

  out.material({{1.0, 0.9, 0.7}, 0.0, 0.5, 0.5, 0.5, 37.0, 0.0, 1.0});
  emit_node(size, {0.0, 0.0, 0.0}, 0.5, {0.0, 0.0, 1.0}, make_object_set(), out);
}

}  // namespace raygate::scenes

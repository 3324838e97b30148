// jacks (spd-spec.md §3.10, by A. Enzmann): recursive jacks, each 3 axis cylinders with a
// sphere at each of its 6 ends, with 8 half-size jacks in its octants. The SPD builds it with a
// transform stack; NFF has no transforms, so points go through the 4x4 and radii are scaled by
// the length of the matrix's first row (§1.5).
#include <array>
#include <cmath>
#include <numbers>

#include "generators/generators.h"
#include "lib/matrix.h"
#include "lib/tessellate.h"

namespace raygate::scenes {
namespace {

constexpr int kForcedResolution = 2;  // jacks tessellates at 2 whatever -t says (§4)

double degrees(double d) { return d * std::numbers::pi / 180.0; }

// Uniform scale of a transform: the length of its first row (§1.5).
double radius_scale(const Matrix4& m) {
  return std::sqrt(m.m[0][0] * m.m[0][0] + m.m[0][1] * m.m[0][1] + m.m[0][2] * m.m[0][2]);
}

void emit_sphere(const Vec3& center, double radius, const Matrix4& m, NffWriter& out) {
  const Vec3 c = transform_point(center, m);
  const double r = radius * radius_scale(m);
  if (out.mode() != OutputMode::tessellated) {
    out.sphere(c, r);
    return;
  }
  for (const PatchTriangle& t : tessellate_sphere(c, r, kForcedResolution)) {
    out.patch(t.vertices, t.normals);
  }
}

void emit_cylinder(const Vec3& from, const Vec3& to, double radius, const Matrix4& m,
                   NffWriter& out) {
  const Vec3 a = transform_point(from, m);
  const Vec3 b = transform_point(to, m);
  const double r = radius * radius_scale(m);
  if (out.mode() != OutputMode::tessellated) {
    out.cone(a, r, b, r);
    return;
  }
  for (const PatchTriangle& t : tessellate_cone(a, r, b, r, kForcedResolution)) {
    out.patch(t.vertices, t.normals);
  }
}

void jack(int level, int size, const Matrix4& m, NffWriter& out) {
  // The jack itself is drawn at 0.75 scale (applied to the point before M).
  const Matrix4 local = Matrix4::scale(0.75, 0.75, 0.75) * m;
  const std::array<Vec3, 3> axes{{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (const Vec3& a : axes) emit_cylinder(-a, a, 0.1, local, out);
  for (const Vec3& a : axes) emit_sphere(a, 0.2, local, out);
  for (const Vec3& a : axes) emit_sphere(-a, 0.2, local, out);
  if (level >= size) return;
  // Eight half-size jacks, one per octant: scale, then translate, then this jack's transform
  // without its 0.75 (the scale is local to the jack's own parts; Table B's boxes confirm it).
  for (double i : {-0.5, 0.5}) {
    for (double j : {-0.5, 0.5}) {
      for (double k : {-0.5, 0.5}) {
        const Matrix4 child = Matrix4::scale(0.5, 0.5, 0.5) * Matrix4::translate({i, j, k}) * m;
        jack(level + 1, size, child, out);
      }
    }
  }
}

}  // namespace

void generate_jacks(int size, NffWriter& out) {
  out.background({0.2, 0.05, 0.2});
  out.view({0.0, 0.0, -8.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 25.0, 0.001, 256, 256);
  out.light({-10.0, 3.0, -20.0});
  out.material({{0.737, 0.561, 0.561}, 0.1, 0.7, 0.7, 0.4, 20.0, 0.0, 1.0});
  // Root: rotate about Y by −20°, then about X by −30°.
  const Matrix4 root = Matrix4::rotate_y(degrees(-20.0)) * Matrix4::rotate_x(degrees(-30.0));
  jack(1, size, root, out);
}

}  // namespace raygate::scenes

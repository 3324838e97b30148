// 4x4 transforms in the SPD library's convention (spd-spec.md §2.2): row vectors, p' = p·M,
// translation in row 3, so "apply A, then B" is the product A·B. Sums run left to right as the
// spec prescribes, which keeps generated scenes bit-identical to the published ones.
#pragma once

#include <array>

#include "geom/vec3.h"

namespace raygate::scenes {

struct Matrix4 {
  std::array<std::array<double, 4>, 4> m{};

  static Matrix4 identity();
  static Matrix4 scale(double sx, double sy, double sz);
  static Matrix4 translate(const Vec3& offset);
  static Matrix4 rotate_x(double radians);
  static Matrix4 rotate_y(double radians);
  static Matrix4 rotate_z(double radians);
  // Rodrigues' rotation about a unit axis.
  static Matrix4 rotate_axis(const Vec3& unit_axis, double radians);
};

// Σ_k a[i][k]·b[k][j], k = 0..3 added left to right.
Matrix4 operator*(const Matrix4& a, const Matrix4& b);

// p·M including the translation row.
Vec3 transform_point(const Vec3& p, const Matrix4& m);
// v·M without the translation row.
Vec3 transform_vector(const Vec3& v, const Matrix4& m);

}  // namespace raygate::scenes

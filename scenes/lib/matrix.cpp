#include "lib/matrix.h"

#include <cmath>

namespace raygate::scenes {

Matrix4 Matrix4::identity() {
  Matrix4 r;
  for (int i = 0; i < 4; ++i) r.m[i][i] = 1.0;
  return r;
}

Matrix4 Matrix4::scale(double sx, double sy, double sz) {
  Matrix4 r = identity();
  r.m[0][0] = sx;
  r.m[1][1] = sy;
  r.m[2][2] = sz;
  return r;
}

Matrix4 Matrix4::translate(const Vec3& offset) {
  Matrix4 r = identity();
  r.m[3][0] = offset.x;
  r.m[3][1] = offset.y;
  r.m[3][2] = offset.z;
  return r;
}

Matrix4 Matrix4::rotate_x(double radians) {
  const double c = std::cos(radians);
  const double s = std::sin(radians);
  Matrix4 r = identity();
  r.m[1][1] = c;
  r.m[2][2] = c;
  r.m[1][2] = s;
  r.m[2][1] = -s;
  return r;
}

Matrix4 Matrix4::rotate_y(double radians) {
  const double c = std::cos(radians);
  const double s = std::sin(radians);
  Matrix4 r = identity();
  r.m[0][0] = c;
  r.m[2][2] = c;
  r.m[2][0] = s;
  r.m[0][2] = -s;
  return r;
}

Matrix4 Matrix4::rotate_z(double radians) {
  const double c = std::cos(radians);
  const double s = std::sin(radians);
  Matrix4 r = identity();
  r.m[0][0] = c;
  r.m[1][1] = c;
  r.m[0][1] = s;
  r.m[1][0] = -s;
  return r;
}

Matrix4 Matrix4::rotate_axis(const Vec3& k, double radians) {
  const double c = std::cos(radians);
  const double s = std::sin(radians);
  const double t = 1.0 - c;
  Matrix4 r = identity();
  r.m[0][0] = k.x * k.x + (1.0 - k.x * k.x) * c;
  r.m[0][1] = k.x * k.y * t + k.z * s;
  r.m[0][2] = k.x * k.z * t - k.y * s;
  r.m[1][0] = k.x * k.y * t - k.z * s;
  r.m[1][1] = k.y * k.y + (1.0 - k.y * k.y) * c;
  r.m[1][2] = k.y * k.z * t + k.x * s;
  r.m[2][0] = k.x * k.z * t + k.y * s;
  r.m[2][1] = k.y * k.z * t - k.x * s;
  r.m[2][2] = k.z * k.z + (1.0 - k.z * k.z) * c;
  return r;
}

Matrix4 operator*(const Matrix4& a, const Matrix4& b) {
  Matrix4 r;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      double sum = 0.0;
      for (int k = 0; k < 4; ++k) sum += a.m[i][k] * b.m[k][j];
      r.m[i][j] = sum;
    }
  }
  return r;
}

Vec3 transform_point(const Vec3& p, const Matrix4& m) {
  return {p.x * m.m[0][0] + p.y * m.m[1][0] + p.z * m.m[2][0] + m.m[3][0],
          p.x * m.m[0][1] + p.y * m.m[1][1] + p.z * m.m[2][1] + m.m[3][1],
          p.x * m.m[0][2] + p.y * m.m[1][2] + p.z * m.m[2][2] + m.m[3][2]};
}

Vec3 transform_vector(const Vec3& v, const Matrix4& m) {
  return {v.x * m.m[0][0] + v.y * m.m[1][0] + v.z * m.m[2][0],
          v.x * m.m[0][1] + v.y * m.m[1][1] + v.z * m.m[2][1],
          v.x * m.m[0][2] + v.y * m.m[1][2] + v.z * m.m[2][2]};
}

}  // namespace raygate::scenes

// SPD "rings", spd-spec.md §3.4: a pyramid of objects seen from its tip, each object 6
// pentagonal rings (30 cylinders, 30 spheres) through the edge midpoints of a dodecahedron,
// in front of a white backdrop wall; 3 lights.
#include <array>
#include <cmath>
#include <numbers>

#include "generators/generators.h"
#include "lib/matrix.h"

namespace raygate::scenes {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kRadius = 0.07412;  // cylinders and spheres alike
constexpr int kRingPoints = 30;

using RingPoints = std::array<Vec3, kRingPoints>;

// Pentagon 0 in the z = 0 plane, then 5 copies tipped about X and turned about Z (§3.4).
RingPoints make_ring_points() {
  RingPoints points;
  const double sc = 1.0 / (1.0 + kRadius);
  for (int k = 0; k < 5; ++k) {
    const double angle = 2.0 * kPi * k / 5.0;
    points[k] = Vec3{std::cos(angle), std::sin(angle), 0.0} * sc;
  }
  const Matrix4 tip = Matrix4::rotate_x(2.0 * std::acos(std::cos(kPi / 3.0) / std::sin(kPi / 5.0)));
  for (int p = 1; p <= 5; ++p) {
    const Matrix4 turn = Matrix4::rotate_z(kPi * (2.0 * (p - 1) + 1.0) / 5.0);
    for (int k = 0; k < 5; ++k) {
      points[5 * p + k] = transform_vector(transform_vector(points[k], tip), turn);
    }
  }
  return points;
}

// One object: for each ring, its colour, then per element a cylinder to the previous element
// of the ring and a sphere at the element.
void emit_object(const RingPoints& points, const Vec3& offset, NffWriter& out) {
  static constexpr std::array<Vec3, 6> kColors{{{1.0, 0.0, 0.0},
                                                {0.0, 1.0, 0.0},
                                                {0.0, 0.0, 1.0},
                                                {0.0, 1.0, 1.0},
                                                {1.0, 0.0, 1.0},
                                                {1.0, 1.0, 0.0}}};
  for (int e = 0; e < kRingPoints; ++e) {
    int previous = e - 1;
    if (e % 5 == 0) {
      previous = e + 4;
      out.material({kColors[e / 5], 0.0, 0.5, 0.2, 0.3, 37.0, 0.0, 0.0});
    }
    const Vec3 base = points[e] + offset;
    const Vec3 apex = points[previous] + offset;
    out.cone(base, kRadius, apex, kRadius);
    out.sphere(base, kRadius);
  }
}

}  // namespace

void generate_rings(int size, NffWriter& out) {
  const double spread = 1.0 / std::sin(kPi / 8.0);
  const double y_diff = spread;
  const double xz_diff = 1.0;
  const Vec3 from{-1.0, -spread, 0.5};

  out.background({0.078, 0.361, 0.753});
  out.view(from, from + Vec3{0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}, 45.0, 1.0, 512, 512);
  out.light({3.0, -spread, 3.0});
  out.light({-4.0, -spread, 1.0});
  out.light({2.0, -spread, -4.0});

  // The wall just fills the 45° view at the back of the pyramid, facing the eye (-y).
  out.material({{1.0, 1.0, 1.0}, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  const double wy = y_diff * (size + 1);
  const double w = 1.01 * (wy - from.y) * std::tan(kPi / 8.0);
  const std::array<Vec3, 4> wall{{{from.x + w, wy, from.z + w},
                                  {from.x - w, wy, from.z + w},
                                  {from.x - w, wy, from.z - w},
                                  {from.x + w, wy, from.z - w}}};
  out.polygon(wall);

  const RingPoints points = make_ring_points();
  for (int d = 0; d < size; ++d) {
    for (int oz = 0; oz <= d; ++oz) {
      for (int ox = 0; ox <= d; ++ox) {
        const Vec3 offset{xz_diff * (2 * ox - d), y_diff * (d + 1), xz_diff * (2 * oz - d)};
        emit_object(points, offset, out);
      }
    }
  }
}

}  // namespace raygate::scenes

// SPD "gears", spd-spec.md §3.2: a size³ block of meshing 36-tooth gears (concave 144-gon top
// and bottom, 144 side quads), some transparent, on a reflective ground square; 5 lights.
#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "generators/generators.h"

namespace raygate::scenes {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr int kTeeth = 36;
constexpr double kToothAngle = 2.0 * kPi / kTeeth;

// frac(a) = a - trunc(a); the argument is (integer·5.0)/7.0 style, multiply then divide, so
// multiples of 7 come out exact (§3.2 "Bit-exact").
double fraction(double a) { return a - std::trunc(a); }

Vec3 gear_color(int ix, int iy, int iz) {
  const double r = 0.01 + fraction((ix * 3 + iy * 2 + iz + 1) * 5.0 / 7.0);
  const double g = 0.01 + fraction((iy * 3 + iz * 2 + ix + 1) * 3.0 / 7.0);
  const double b = 0.01 + fraction((iz * 3 + ix * 2 + iy + 1) * 2.0 / 7.0);
  const double largest = std::max({r, g, b});
  return {r / largest, g / largest, b / largest};
}

SpdMaterial gear_material(int ix, int iy, int iz) {
  const Vec3 color = gear_color(ix, iy, iz);
  if ((ix * 4 + iy * 2 + iz) % 5 == 0) return {color, 0.0, 0.2, 0.0, 0.0, 0.0, 0.8, 1.1};
  return {color, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
}

struct GearShape {
  Vec3 center;   // centre of the top face
  double phase;  // angular offset φ0 (alternate gears shifted half a tooth)
  double outer;  // tooth tip radius
  double inner;  // tooth root radius
  double thickness;
};

Vec3 rim_point(const Vec3& center, double radius, double angle, double z) {
  return {center.x + radius * std::cos(angle), center.y + radius * std::sin(angle), z};
}

// The 144-vertex outline (§3.2 steps 1 and 3). `sense` is +1 for the counter-clockwise top and
// -1 for the clockwise bottom: it negates both the tooth step and the tooth profile. Negation is
// exact, so g + (-x) gives the same bits as the spec's g - x.
std::vector<Vec3> outline(const GearShape& gear, double sense, double z) {
  const double a = sense * kToothAngle;
  std::vector<Vec3> points;
  points.reserve(4 * kTeeth);
  for (int k = 0; k < kTeeth; ++k) {
    const double g = gear.phase + sense * (2.0 * kPi * k / kTeeth);
    points.push_back(rim_point(gear.center, gear.outer, g - 0.19 * a, z));
    points.push_back(rim_point(gear.center, gear.outer, g + 0.19 * a, z));
    points.push_back(rim_point(gear.center, gear.inner, g + 0.3 * a, z));
    points.push_back(rim_point(gear.center, gear.inner, g + 0.7 * a, z));
  }
  return points;
}

void emit_gear(const GearShape& gear, NffWriter& out) {
  const std::vector<Vec3> top = outline(gear, 1.0, gear.center.z);
  out.polygon(top);
  const Vec3 down{0.0, 0.0, gear.thickness};
  for (std::size_t k = 0; k < top.size(); ++k) {
    const Vec3& p = top[k];
    const Vec3& q = top[(k + 1) % top.size()];
    const std::array<Vec3, 4> side{{p, p - down, q - down, q}};
    out.polygon(side);
  }
  out.polygon(outline(gear, -1.0, gear.center.z - gear.thickness));
}

}  // namespace

void generate_gears(int size, NffWriter& out) {
  out.background({0.078, 0.361, 0.753});
  out.view({-1.1, -2.1, 2.6}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 45.0, 1.0, 512, 512);
  out.light({2.0, 4.0, 4.0});
  out.light({-2.0, 4.0, 3.0});
  out.light({2.0, -2.5, 2.5});
  out.light({-1.0, -4.0, 2.0});
  out.light({-1.111, -2.121, 2.626});

  out.material({{1.0, 0.85, 0.7}, 0.0, 0.3, 0.6, 0.3, 37.0, 0.0, 0.0});
  const std::array<Vec3, 4> ground{
      {{2.0, 2.0, 0.0}, {-2.0, 2.0, 0.0}, {-2.0, -2.0, 0.0}, {2.0, -2.0, 0.0}}};
  out.polygon(ground);

  // §3.2 layout: gears of radius R overlap by the edge difference 0.1·R so the teeth mesh.
  const int n = size;
  const double radius = 1.0 / (n - (n - 1) * 0.05);
  const double step = radius * (2.0 - 0.1);
  const double x0 = -1.0 + radius;
  const double y0 = -1.0 + radius;
  const double thickness = std::min(0.1, 1.0 / (2.0 * n));
  for (int iz = 0; iz < n; ++iz) {
    for (int iy = 0; iy < n; ++iy) {
      for (int ix = 0; ix < n; ++ix) {
        out.material(gear_material(ix, iy, iz));
        const GearShape gear{{x0 + ix * step, y0 + iy * step, 1.0 - static_cast<double>(iz) / n},
                             kPi * ((ix + iy + iz) % 2) / kTeeth,
                             0.995 * radius,
                             0.9 * radius,
                             thickness};
        emit_gear(gear, out);
      }
    }
  }
}

}  // namespace raygate::scenes

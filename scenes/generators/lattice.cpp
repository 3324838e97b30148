// lattice (spd-spec.md §3.8, by A. Costa): a cubic lattice of (n+1)³ shiny spheres joined by
// matte red, green and blue cylinders along x, y and z; 6 lights; the view depends on n.
#include <array>
#include <cmath>

#include "generators/generators.h"

namespace raygate::scenes {
namespace {

const Vec3 kSkyBlue{0.078, 0.361, 0.753};  // "UNC sky blue" (§2.2)

// (colour; ka, kd, ks, ks_spec, ang, kt, ior) as §3.8 gives them.
const SpdMaterial kSphereMaterial{{0.9, 0.9, 0.9}, 0.0, 0.5, 0.5, 0.5, 37.0, 0.0, 0.0};
const std::array<SpdMaterial, 3> kRodMaterials{{
    {{0.9, 0.1, 0.1}, 0.1, 0.99, 0.0, 0.0, 0.0, 0.0, 0.0},  // along x: red
    {{0.1, 0.9, 0.1}, 0.1, 0.99, 0.0, 0.0, 0.0, 0.0, 0.0},  // along y: green
    {{0.1, 0.1, 0.9}, 0.1, 0.99, 0.0, 0.0, 0.0, 0.0, 0.0},  // along z: blue
}};

// p with its coordinate `axis` replaced by `value`.
Vec3 with_coordinate(Vec3 p, int axis, double value) {
  (axis == 0 ? p.x : (axis == 1 ? p.y : p.z)) = value;
  return p;
}

void write_header(int n, double inv, NffWriter& out) {
  out.background(kSkyBlue);
  // The eye sits just off the middle column of the lattice, looking down through it.
  const double x = ((n >> 1) + 0.5) * inv;
  const double half_cell = 1.0 / (2.0 * n);
  out.view({x, 1.0, 1.0 - half_cell}, {x, -1.0, -1.0 - half_cell}, {0.2, 1.0, 0.0}, 60.0, 0.0, 512,
           512);
  for (const Vec3& l : {Vec3{2, .5, .5}, Vec3{-1, .5, .5}, Vec3{.5, 2, .5}, Vec3{.5, -1, .5},
                        Vec3{.5, .5, 2}, Vec3{.5, .5, -1}}) {
    out.light(l);
  }
}

}  // namespace

void generate_lattice(int size, NffWriter& out) {
  const int n = size;
  const double r1 = 0.25 / n;    // sphere radius
  const double r2 = 0.0625 / n;  // rod radius
  const double inv = 1.0 / n;
  // Rods start a little inside each sphere so they meet its surface (§3.8's δ).
  const double delta = r1 * (1.0 - std::sqrt(0.0625 / 0.25)) * 0.99;
  write_header(n, inv, out);

  for (int x = 0; x <= n; ++x) {
    for (int y = 0; y <= n; ++y) {
      for (int z = 0; z <= n; ++z) {
        const Vec3 p{static_cast<double>(x) / n, static_cast<double>(y) / n,
                     static_cast<double>(z) / n};
        out.material(kSphereMaterial);
        out.sphere(p, r1);
        const std::array<bool, 3> has_rod{x != n, y != n, z != n};
        for (int axis = 0; axis < 3; ++axis) {
          if (!has_rod[axis]) continue;
          out.material(kRodMaterials[axis]);
          out.cone(with_coordinate(p, axis, p[axis] + delta), r2,
                   with_coordinate(p, axis, p[axis] + inv - delta), r2);
        }
      }
    }
  }
}

}  // namespace raygate::scenes

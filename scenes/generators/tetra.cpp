// SPD "tetra", spd-spec.md §3.6: a recursive Sierpinski tetrahedron of 4^size triangles, with
// the view and light of Kay & Kajiya's test scene; 1 light, mostly background.
#include <array>

#include "generators/generators.h"

namespace raygate::scenes {
namespace {

// Cube corners with dx·dy·dz = +1, in x-then-y-then-z loop order (§3.6).
constexpr std::array<Vec3, 4> kCorners{
    {{-1.0, -1.0, 1.0}, {-1.0, 1.0, -1.0}, {1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}}};

void emit_tetrahedron(int depth, const Vec3& center, double half_size, NffWriter& out) {
  if (depth <= 1) {
    std::array<Vec3, 4> v;
    for (int i = 0; i < 4; ++i) v[i] = center + kCorners[i] * half_size;
    // All four faces counter-clockwise seen from outside.
    out.polygon(std::array<Vec3, 3>{v[0], v[1], v[2]});
    out.polygon(std::array<Vec3, 3>{v[3], v[2], v[1]});
    out.polygon(std::array<Vec3, 3>{v[2], v[3], v[0]});
    out.polygon(std::array<Vec3, 3>{v[1], v[0], v[3]});
    return;
  }
  // Powers of two throughout, so every coordinate is exact.
  for (const Vec3& corner : kCorners) {
    emit_tetrahedron(depth - 1, center + corner * half_size / 2.0, half_size / 2.0, out);
  }
}

}  // namespace

void generate_tetra(int size, NffWriter& out) {
  out.background({0.078, 0.361, 0.753});
  // The unrounded camera; the writer's %g shows `from` as 1.02285 -3.17715 -2.17451.
  out.view({1.022846, -3.177154, -2.174512}, {-0.004103, -0.004103, 0.216539},
           {-0.816497, -0.816497, 0.816497}, 45.0, 1.0, 512, 512);
  out.light({2.0, -18.0, -5.0});
  out.material({{1.0, 0.2, 0.2}, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  emit_tetrahedron(size, {0.0, 0.0, 0.0}, 1.0, out);
}

}  // namespace raygate::scenes

// SPD "teapot", spd-spec.md §3.5: the Newell teapot (with Crow's bottom), 32 bicubic Bezier
// patches each tessellated into n×n quads split into smooth triangles (`pp`), on an n×n
// checkerboard; 2 lights.
#include <array>
#include <cmath>

#include "generators/generators.h"
#include "generators/teapot_data.h"

namespace raygate::scenes {
namespace {

using Mat4 = std::array<std::array<double, 4>, 4>;
using Row4 = std::array<double, 4>;

// The cubic Bezier basis in power form (§3.5).
constexpr Mat4 kBezier{
    {{-1.0, 3.0, -3.0, 1.0}, {3.0, -6.0, 3.0, 0.0}, {-3.0, 3.0, 0.0, 0.0}, {1.0, 0.0, 0.0, 0.0}}};

// a·b with the terms added left to right, as the spec's bit-exact order asks (§2.3).
double dot4(const Row4& a, const Row4& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 r{};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) r[i][j] = dot4(a[i], {b[0][j], b[1][j], b[2][j], b[3][j]});
  }
  return r;
}

Mat4 transpose(const Mat4& a) {
  Mat4 r{};
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) r[i][j] = a[j][i];
  }
  return r;
}

// Mb·G·Mbᵀ for each coordinate of one patch.
struct PatchBasis {
  std::array<Mat4, 3> mgm;
};

PatchBasis patch_basis(int patch) {
  PatchBasis basis;
  const auto& indices = teapot_data::kPatches[patch];
  for (int axis = 0; axis < 3; ++axis) {
    Mat4 g{};
    for (int r = 0; r < 4; ++r) {
      for (int c = 0; c < 4; ++c) g[r][c] = teapot_data::kPoints[indices[4 * r + c]][axis];
    }
    basis.mgm[axis] = multiply(multiply(kBezier, g), transpose(kBezier));
  }
  return basis;
}

// [u³, u², u, 1] and its derivative [3u², 2u, 1, 0], powers by repeated multiplication.
Row4 powers(double u) { return {u * u * u, u * u, u, 1.0}; }
Row4 derivative_powers(double u) { return {u * u * 3.0, u * 2.0, 1.0, 0.0}; }

// S·MGM·Tᵀ per coordinate.
Vec3 evaluate(const PatchBasis& basis, const Row4& s, const Row4& t) {
  std::array<double, 3> p{};
  for (int axis = 0; axis < 3; ++axis) {
    const Mat4& m = basis.mgm[axis];
    const Row4 sm{dot4(s, {m[0][0], m[1][0], m[2][0], m[3][0]}),
                  dot4(s, {m[0][1], m[1][1], m[2][1], m[3][1]}),
                  dot4(s, {m[0][2], m[1][2], m[2][2], m[3][2]}),
                  dot4(s, {m[0][3], m[1][3], m[2][3], m[3][3]})};
    p[axis] = dot4(sm, t);
  }
  return {p[0], p[1], p[2]};
}

struct SurfacePoint {
  Vec3 position;
  Vec3 normal;
};

SurfacePoint surface_point(const PatchBasis& basis, double s, double t) {
  const Row4 sp = powers(s);
  const Row4 tp = powers(t);
  const Vec3 ds = evaluate(basis, derivative_powers(s), tp);
  const Vec3 dt = evaluate(basis, sp, derivative_powers(t));
  return {evaluate(basis, sp, tp), normalize(cross(dt, ds))};
}

bool on_axis(const Vec3& p) { return std::abs(p.x) <= 1e-4 && std::abs(p.y) <= 1e-4; }

// The cusp rule (§3.5): a triangle touching the z axis at 2+ vertices is degenerate and
// dropped; with 1 such vertex that vertex's (undefined) normal becomes ±z.
void emit_triangle(std::array<SurfacePoint, 3> tri, NffWriter& out) {
  int cusps = 0;
  for (const SurfacePoint& v : tri) cusps += on_axis(v.position) ? 1 : 0;
  if (cusps >= 2) return;
  std::array<Vec3, 3> vertices;
  std::array<Vec3, 3> normals;
  for (int i = 0; i < 3; ++i) {
    if (cusps == 1 && on_axis(tri[i].position)) {
      tri[i].normal = {0.0, 0.0, tri[i].position.z > 1.5 ? 1.0 : -1.0};
    }
    vertices[i] = tri[i].position;
    normals[i] = tri[i].normal;
  }
  out.patch(vertices, normals);
}

void emit_patch(int patch, int n, NffWriter& out) {
  const PatchBasis basis = patch_basis(patch);
  const auto at = [&](int i, int j) {
    return surface_point(basis, static_cast<double>(i) / n, static_cast<double>(j) / n);
  };
  for (int ss = 0; ss < n; ++ss) {
    for (int tt = 0; tt < n; ++tt) {
      const SurfacePoint c0 = at(ss, tt);
      const SurfacePoint c1 = at(ss, tt + 1);
      const SurfacePoint c2 = at(ss + 1, tt + 1);
      const SurfacePoint c3 = at(ss + 1, tt);
      emit_triangle({c0, c1, c2}, out);
      emit_triangle({c2, c3, c0}, out);
    }
  }
}

// The n×n board over [-4, 4]²: first the squares with s + t odd, then the even ones.
void emit_checkerboard(int n, NffWriter& out) {
  const auto coord = [n](int i) { return 4.0 * (2.0 * i / n - 1.0); };
  for (int parity = 1; parity >= 0; --parity) {
    const double grey = parity == 1 ? 1.0 : 0.5;
    out.material({{grey, grey, grey}, 0.0, 0.5, 0.5, 0.5, 30.0, 0.0, 0.0});
    for (int s = 0; s < n; ++s) {
      for (int t = 0; t < n; ++t) {
        if ((s + t) % 2 != parity) continue;
        const std::array<Vec3, 4> square{{{coord(s), coord(t), 0.0},
                                          {coord(s + 1), coord(t), 0.0},
                                          {coord(s + 1), coord(t + 1), 0.0},
                                          {coord(s), coord(t + 1), 0.0}}};
        out.polygon(square);
      }
    }
  }
}

}  // namespace

void generate_teapot(int size, NffWriter& out) {
  // The SPD warns on stderr that size 1 is "not supported" (§3.5, §8); a library stays quiet
  // and writes the same scene.
  out.background({0.078, 0.361, 0.753});
  out.view({4.86, 7.2, 5.4}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 45.0, 1.0, 512, 512);
  out.light({-3.1, 9.8, 12.1});
  out.light({11.3, 5.1, 8.8});
  emit_checkerboard(size, out);
  out.material({{1.0, 0.5, 0.1}, 0.0, 0.75, 0.25, 0.25, 37.0, 0.0, 0.0});
  for (int patch = 0; patch < teapot_data::kPatchCount; ++patch) emit_patch(patch, size, out);
}

}  // namespace raygate::scenes

// nurbtst (spd-spec.md §3.13): the SPD's NURBS demo, one bicubic B-spline patch on a 6 x 5
// control grid, always tessellated to `pp` triangles at the forced resolution 5. The SPD
// evaluates it in single precision, so this file does too (float basis functions, parameters
// accumulated in float); the transform and the writer then work in double as for every scene.
// The size factor is ignored.
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

#include "generators/generators.h"
#include "lib/matrix.h"

namespace raygate::scenes {
namespace {

constexpr int kOrder = 4;  // cubic in both directions
constexpr int kDegree = kOrder - 1;
constexpr int kRowsU = 6;       // control rows i (the y coordinate), along u
constexpr int kColsV = 5;       // control columns j (the x coordinate), along v
constexpr int kResolution = 5;  // forced: 5 steps per control point (§4)

// Open uniform knot vectors (§3.13). The data's weights are ignored by the SPD evaluator.
const std::array<float, kRowsU + kOrder> kKnotsU{0, 0, 0, 0, 1, 2, 3, 3, 3, 3};
const std::array<float, kColsV + kOrder> kKnotsV{0, 0, 0, 0, 1, 2, 2, 2, 2};

// z of control point (j, i): rows 1 and 4 are flat, rows 2 and 3 have a bump in the middle.
const std::array<std::array<float, kColsV>, kRowsU> kHeights{{
    {0, 3, -3, 3, 0},
    {0, 0, 0, 0, 0},
    {0, 0, 5, 0, 0},
    {0, 0, 5, 0, 0},
    {0, 0, 0, 0, 0},
    {0, -3, 3, -3, 0},
}};

struct FVec3 {
  float x = 0, y = 0, z = 0;
};

// The B-spline basis of one direction at t: the kOrder functions that can be non-zero,
// N[span − kDegree + r] for r = 0..kDegree, and their derivatives.
struct Basis {
  int first = 0;  // index of the first non-zero function
  std::array<float, kOrder> value{};
  std::array<float, kOrder> derivative{};
};

// The last knot interval [k_s, k_{s+1}) holding t; t at or past the end uses the last
// non-empty interval (float accumulation can step a hair past it).
template <std::size_t N>
int find_span(const std::array<float, N>& knots, int count, float t) {
  int span = kDegree;
  while (span + 1 < count && knots[span + 1] <= t) ++span;
  return span;
}

// Cox–de Boor up to `degree` at t for the functions ending at `span` (degree + 1 values).
template <std::size_t N>
std::array<float, kOrder> cox_de_boor(const std::array<float, N>& k, int span, float t,
                                      int degree) {
  std::array<float, kOrder> n{1.0f};
  std::array<float, kOrder> left{}, right{};
  for (int d = 1; d <= degree; ++d) {
    left[d] = t - k[span + 1 - d];
    right[d] = k[span + d] - t;
    float saved = 0.0f;
    for (int r = 0; r < d; ++r) {
      const float term = n[r] / (right[r + 1] + left[d - r]);
      n[r] = saved + right[r + 1] * term;
      saved = left[d - r] * term;
    }
    n[d] = saved;
  }
  return n;
}

template <std::size_t N>
Basis basis(const std::array<float, N>& knots, int count, float t) {
  const int span = find_span(knots, count, t);
  Basis b;
  b.first = span - kDegree;
  b.value = cox_de_boor(knots, span, t, kDegree);
  // N'_{i,p} = p·(N_{i,p−1}/(k_{i+p} − k_i) − N_{i+1,p−1}/(k_{i+p+1} − k_{i+1})).
  const std::array<float, kOrder> lower = cox_de_boor(knots, span, t, kDegree - 1);
  for (int r = 0; r <= kDegree; ++r) {
    const int i = b.first + r;
    const float a = r >= 1 ? lower[r - 1] : 0.0f;
    const float c = r <= kDegree - 1 ? lower[r] : 0.0f;
    const float da = knots[i + kDegree] - knots[i];
    const float dc = knots[i + kDegree + 1] - knots[i + 1];
    b.derivative[r] = kDegree * ((da != 0.0f ? a / da : 0.0f) - (dc != 0.0f ? c / dc : 0.0f));
  }
  return b;
}

FVec3 control_point(int i, int j) {
  return {static_cast<float>(j), static_cast<float>(i), kHeights[i][j]};
}

// Σ_i Σ_j wu_i·wv_j·P_ij over the non-zero basis functions.
FVec3 combine(const Basis& bu, const std::array<float, kOrder>& wu, const Basis& bv,
              const std::array<float, kOrder>& wv) {
  FVec3 sum;
  for (int a = 0; a < kOrder; ++a) {
    for (int b = 0; b < kOrder; ++b) {
      const float w = wu[a] * wv[b];
      const FVec3 p = control_point(bu.first + a, bv.first + b);
      sum.x += w * p.x;
      sum.y += w * p.y;
      sum.z += w * p.z;
    }
  }
  return sum;
}

struct SurfacePoint {
  Vec3 position;
  Vec3 normal;
};

// The point and its normal normalize(∂P/∂v × ∂P/∂u), all in float (§3.13).
SurfacePoint evaluate(float u, float v) {
  const Basis bu = basis(kKnotsU, kRowsU, u);
  const Basis bv = basis(kKnotsV, kColsV, v);
  const FVec3 p = combine(bu, bu.value, bv, bv.value);
  const FVec3 du = combine(bu, bu.derivative, bv, bv.value);
  const FVec3 dv = combine(bu, bu.value, bv, bv.derivative);
  const FVec3 n{dv.y * du.z - dv.z * du.y, dv.z * du.x - dv.x * du.z, dv.x * du.y - dv.y * du.x};
  const float len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  return {{p.x, p.y, p.z}, {n.x / len, n.y / len, n.z / len}};
}

// Translate to the middle of the grid, stand it up (x by −90°), turn it by 30° about y.
Matrix4 placement() {
  const double deg = std::numbers::pi / 180.0;
  return Matrix4::translate({-2.0, -2.5, 0.0}) * Matrix4::rotate_x(-90.0 * deg) *
         Matrix4::rotate_y(30.0 * deg);
}

// grid[iv][iu]: (kColsV·5 + 1) x (kRowsU·5 + 1) points with parameters accumulated in float.
std::vector<std::vector<SurfacePoint>> sample_surface(const Matrix4& m) {
  const int steps_u = kRowsU * kResolution;  // 30 steps over [0, 3]
  const int steps_v = kColsV * kResolution;  // 25 steps over [0, 2]
  const float u0 = kKnotsU[kDegree], u1 = kKnotsU[kRowsU];
  const float v0 = kKnotsV[kDegree], v1 = kKnotsV[kColsV];
  const float du = (u1 - u0) / static_cast<float>(steps_u);
  const float dv = (v1 - v0) / static_cast<float>(steps_v);
  std::vector<std::vector<SurfacePoint>> grid(steps_v + 1);
  float v = v0;
  for (auto& row : grid) {
    float u = u0;
    for (int k = 0; k <= steps_u; ++k) {
      const SurfacePoint s = evaluate(u, v);
      // Placement is a pure rotation plus translation, so normals turn with the same matrix.
      row.push_back({transform_point(s.position, m), normalize(transform_vector(s.normal, m))});
      u += du;
    }
    v += dv;
  }
  return grid;
}

void write_header(NffWriter& out) {
  out.background({0.0, 0.0, 0.0});
  out.view({0.0, 5.0, -10.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 30.0, 0.001, 256, 256);
  out.light({0.0, 50.0, -10.0});
  out.material({{1.0, 0.0, 0.0}, 0.1, 0.7, 0.0, 0.7, 10.0, 0.0, 1.0});
}

void emit(const SurfacePoint& a, const SurfacePoint& b, const SurfacePoint& c, NffWriter& out) {
  const Vec3 vertices[3] = {a.position, b.position, c.position};
  const Vec3 normals[3] = {a.normal, b.normal, c.normal};
  out.patch(vertices, normals);
}

}  // namespace

void generate_nurbtst(int /*size: ignored*/, NffWriter& out) {
  write_header(out);
  const auto p = sample_surface(placement());
  // Rows i run along v, columns j along u, so each triangle winds counter-clockwise about its
  // vertex normals (§3.13's cell split).
  for (std::size_t i = 1; i < p.size(); ++i) {
    for (std::size_t j = 0; j + 1 < p[i].size(); ++j) {
      emit(p[i - 1][j], p[i][j], p[i][j + 1], out);
      emit(p[i - 1][j], p[i][j + 1], p[i - 1][j + 1], out);
    }
  }
}

}  // namespace raygate::scenes

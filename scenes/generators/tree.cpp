// SPD "tree", spd-spec.md §3.7: a binary branching tree after Aono and Kunii, a cone per
// branch and a sphere at each branch tip, on a large green field; 7 lights.
#include <array>
#include <numbers>

#include "generators/generators.h"
#include "lib/matrix.h"

namespace raygate::scenes {
namespace {

constexpr double kPi = std::numbers::pi;

double radians(double degrees) { return degrees * kPi / 180.0; }

struct BranchRule {
  double branching_degrees;
  double divergence_degrees;
  double contraction;
};

// B = Rx(branching) · Rz(divergence) · S, S = scale by the contraction, then lift by (0,0,1):
// row-vector matrices, so the product applies left factor first (§2.2, §3.7).
Matrix4 branch_matrix(const BranchRule& rule) {
  const Matrix4 rx = Matrix4::rotate_x(radians(rule.branching_degrees));
  const Matrix4 rz = Matrix4::rotate_z(radians(rule.divergence_degrees));
  const double c = rule.contraction;
  const Matrix4 s = Matrix4::scale(c, c, c) * Matrix4::translate({0.0, 0.0, 1.0});
  return rx * rz * s;
}

void grow(const Matrix4& m, double scale, int depth, const std::array<Matrix4, 2>& branches,
          NffWriter& out) {
  const Vec3 base = transform_point({0.0, 0.0, 0.0}, m);
  const Vec3 apex = transform_point({0.0, 0.0, 1.0}, m);
  const double base_radius = 0.15 * scale;
  const double apex_radius = 0.67 * base_radius;
  out.cone(base, base_radius, apex, apex_radius);
  out.sphere(apex, apex_radius);
  if (depth <= 0) return;
  // The child applies its branch matrix first, then the parent's placement.
  for (const Matrix4& b : branches) grow(b * m, 0.67 * scale, depth - 1, branches, out);
}

}  // namespace

void generate_tree(int size, NffWriter& out) {
  out.background({0.078, 0.361, 0.753});
  out.view({4.5, 0.4, 2.0}, {0.0, 0.0, 1.5}, {0.0, 0.0, 1.0}, 45.0, 1.0, 512, 512);
  constexpr std::array<Vec3, 7> kLights{{{-5.0, 5.0, 50.0},
                                         {30.0, -30.0, 30.0},
                                         {-40.0, -30.0, 20.0},
                                         {10.0, 30.0, 40.0},
                                         {-30.0, 40.0, 10.0},
                                         {50.0, 25.0, 20.0},
                                         {-10.0, -60.0, 30.0}}};
  for (const Vec3& l : kLights) out.light(l);

  out.material({{0.2, 0.7, 0.2}, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  const std::array<Vec3, 4> field{
      {{50.0, 50.0, 0.0}, {-50.0, 50.0, 0.0}, {-50.0, -50.0, 0.0}, {50.0, -50.0, 0.0}}};
  out.polygon(field);

  out.material({{0.55, 0.4, 0.2}, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  const std::array<Matrix4, 2> branches{branch_matrix({40.0, 90.0, 0.65}),
                                        branch_matrix({25.0, 140.0 + 90.0, 0.70})};
  grow(Matrix4::identity(), 1.0, size, branches, out);
}

}  // namespace raygate::scenes

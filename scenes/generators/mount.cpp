// SPD "mount", spd-spec.md §3.3: a Carpenter-style midpoint-displacement fractal mountain of
// triangles, with a pyramid of 4 glass spheres in front of it; 1 light.
#include <array>
#include <cmath>
#include <numbers>

#include "generators/generators.h"
#include "lib/matrix.h"

namespace raygate::scenes {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kFractalDimension = 2.2;

// The SPD's "old, buggy" coordinate hash (§3.3), kept for comparability. It is computed in a
// 64-bit unsigned long; shift counts go negative for size ≥ 8, which is undefined in C, and
// x86-64 takes them mod 64 (§8), so they are masked here to reproduce that output.
unsigned long coordinate_hash(unsigned long a, unsigned long b, int size) {
  const auto shift = [](unsigned long v, int count) { return v << (count & 63); };
  return (shift(a, 23 - size) + shift(b, 15 - size) + shift(a, 7 - size)) & 0xFFFFUL;
}

// A Numerical-Recipes-style polar Box-Muller deviate driven by a tiny LCG (§3.3, §8).
double gauss(long seed) {
  constexpr long kMultiplier = 8121;
  constexpr long kIncrement = 28411;
  constexpr long kModulus = 134456;
  long x2 = seed;
  double v1 = 0.0;
  double r = 0.0;
  do {
    const long x1 = (kIncrement + x2 * kMultiplier) % kModulus;
    x2 = (kIncrement + x1 * kMultiplier) % kModulus;
    // Divide, do not multiply by the reciprocal (§3.3 "Bit-exact").
    v1 = static_cast<double>(x1) * 2.0 / kModulus - 1.0;
    const double v2 = static_cast<double>(x2) * 2.0 / kModulus - 1.0;
    r = v1 * v1 + v2 * v2;
  } while (r >= 1.0);
  return v1 * std::sqrt(-2.0 * std::log(r) / r);
}

class Mountain {
 public:
  Mountain(int size, NffWriter& out) : size_(size), cells_(1 << size), out_(out) {
    // Roughness = √(ratio² − 1) with ratio = 2/exp(ln 2/(D − 1)).
    const double ratio = 2.0 / std::exp(std::log(2.0) / (kFractalDimension - 1.0));
    roughness_ = std::sqrt(ratio * ratio - 1.0);
  }

  void run() { cell(cells_, 0, 0, 0.0, 0.0, 0.0, 0.0); }

 private:
  // Seeds depend only on grid coordinates, so shared edges agree and there are no cracks.
  double displacement(int a, int b) const {
    return gauss(21 + static_cast<long>(coordinate_hash(static_cast<unsigned long>(a),
                                                        static_cast<unsigned long>(b), size_)));
  }

  double grid(int i) const { return -1.0 + i * 2.0 / cells_; }

  void cell(int w, int lx, int ly, double ll, double lr, double ur, double ul) {
    if (w == 1) {
      const Vec3 p_ll{grid(lx), grid(ly), ll};
      const Vec3 p_lr{grid(lx + 1), grid(ly), lr};
      const Vec3 p_ur{grid(lx + 1), grid(ly + 1), ur};
      const Vec3 p_ul{grid(lx), grid(ly + 1), ul};
      out_.polygon(std::array<Vec3, 3>{p_ll, p_lr, p_ur});
      out_.polygon(std::array<Vec3, 3>{p_ur, p_ul, p_ll});
      return;
    }
    const int h = w / 2;
    const double rise = h * 2.0 / cells_ * roughness_;
    const double lower = (ll + lr) / 2.0 + rise * displacement(lx + h, ly);
    const double right = (lr + ur) / 2.0 + rise * displacement(lx + w, ly + h);
    const double upper = (ur + ul) / 2.0 + rise * displacement(lx + h, ly + w);
    const double left = (ul + ll) / 2.0 + rise * displacement(lx, ly + h);
    const double middle =
        (ll + lr + ur + ul) / 4.0 + 1.4142136 * rise * displacement(lx + h, ly + h);
    cell(h, lx, ly, ll, lower, middle, left);
    cell(h, lx + h, ly, lower, lr, right, middle);
    cell(h, lx + h, ly + h, middle, right, ur, upper);
    cell(h, lx, ly + h, left, middle, upper, ul);
  }

  int size_;
  int cells_;
  double roughness_ = 0.0;
  NffWriter& out_;
};

// The 4 glass spheres: one on top of a tetrahedral pyramid of three (§3.3).
void emit_glass_spheres(NffWriter& out) {
  out.material({{1.0, 1.0, 1.0}, 0.0, 0.1, 0.1, 0.4, 6.7, 0.9, 1.5});
  const Vec3 center{-0.8, 0.8, 1.0};
  const double radius = 0.17;
  const Vec3 top{0.0, 0.0, radius * std::sqrt(1.5)};
  out.sphere(center + top, radius);
  const Matrix4 tip = Matrix4::rotate_axis(normalize(Vec3{1.0, 1.0, 0.0}), std::acos(-1.0 / 3.0));
  const Vec3 q = transform_vector(top, tip);
  for (int i = 0; i < 3; ++i) {
    const Matrix4 spin = Matrix4::rotate_z(i * 2.0 * kPi / 3.0);
    out.sphere(center + transform_vector(q, spin), radius);
  }
}

}  // namespace

void generate_mount(int size, NffWriter& out) {
  out.background({0.078, 0.361, 0.753});
  out.view({-1.6, 1.6, 1.7}, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0}, 45.0, 0.01, 512, 512);
  out.light({-100.0, -100.0, 100.0});
  emit_glass_spheres(out);
  out.material({{0.5, 0.45, 0.35}, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0});
  Mountain(size, out).run();
}

}  // namespace raygate::scenes

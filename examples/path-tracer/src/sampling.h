// Directions drawn at random, with their probability densities (per steradian): the cosine-
// weighted hemisphere for diffuse bounces and a Phong lobe around the mirror direction for
// glossy ones. Each takes two uniform numbers in [0, 1).
#pragma once

#include <cmath>

#include "vec.h"

namespace nff {

constexpr double kPi = 3.14159265358979323846;

// Two unit vectors that make a right-handed frame with `n` (Duff et al.'s branchless basis).
struct Frame {
  Vec3 tangent, bitangent, normal;

  explicit Frame(Vec3 n) : normal(n) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    tangent = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    bitangent = {b, sign + n.y * n.y * a, -n.y};
  }
  Vec3 to_world(Vec3 local) const {
    return tangent * local.x + bitangent * local.y + normal * local.z;
  }
};

// pdf = cos(theta) / pi about `n`.
inline Vec3 sample_cosine(Vec3 n, double u1, double u2) {
  const double r = std::sqrt(u1);
  const double phi = 2 * kPi * u2;
  return Frame(n).to_world(
      {r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1 - u1))});
}

// pdf = (e + 1) / (2 pi) * cos(alpha)^e about `axis` (alpha: the angle to the axis).
inline Vec3 sample_phong_lobe(Vec3 axis, double exponent, double u1, double u2) {
  const double cos_alpha = std::pow(u1, 1 / (exponent + 1));
  const double sin_alpha = std::sqrt(std::max(0.0, 1 - cos_alpha * cos_alpha));
  const double phi = 2 * kPi * u2;
  return Frame(axis).to_world({sin_alpha * std::cos(phi), sin_alpha * std::sin(phi), cos_alpha});
}

inline double phong_lobe_pdf(Vec3 axis, double exponent, Vec3 direction) {
  const double c = dot(axis, direction);
  return c > 0 ? (exponent + 1) / (2 * kPi) * std::pow(c, exponent) : 0.0;
}

inline Vec3 mirror(Vec3 incoming, Vec3 n) { return incoming - n * (2 * dot(incoming, n)); }

}  // namespace nff

// A ray with a unit direction, plus the small vector helpers the tracer needs on top of vec3.h
// (reflection, refraction, component extremes). Kept separate so vec3.h stays the shared core.
#pragma once

#include <cmath>

#include "geom/vec3.h"

namespace raygate {

struct Ray {
  Vec3 origin;
  Vec3 direction;  // unit length
};

constexpr Vec3 point_at(const Ray& ray, double t) { return ray.origin + ray.direction * t; }

// Largest absolute component: the magnitude that sets a coordinate's rounding error.
inline double max_abs_component(const Vec3& v) {
  return std::fmax(std::fabs(v.x), std::fmax(std::fabs(v.y), std::fabs(v.z)));
}

constexpr Vec3 component_min(const Vec3& a, const Vec3& b) {
  return {a.x < b.x ? a.x : b.x, a.y < b.y ? a.y : b.y, a.z < b.z ? a.z : b.z};
}
constexpr Vec3 component_max(const Vec3& a, const Vec3& b) {
  return {a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z};
}

// Mirror `incoming` (pointing at the surface) about the unit normal `n`.
constexpr Vec3 reflect(const Vec3& incoming, const Vec3& n) {
  return incoming - n * (2.0 * dot(incoming, n));
}

// Snell's law. `incoming` is unit and points at the surface; `n` is the unit normal on the
// incoming side (dot(incoming, n) <= 0); eta = n_incoming / n_transmitted. Returns false on
// total internal reflection, else writes the unit transmitted direction.
inline bool refract(const Vec3& incoming, const Vec3& n, double eta, Vec3& transmitted) {
  const double cos_i = -dot(incoming, n);
  const double sin2_t = eta * eta * (1.0 - cos_i * cos_i);
  if (sin2_t > 1.0) return false;
  const double cos_t = std::sqrt(1.0 - sin2_t);
  transmitted = normalize(incoming * eta + n * (eta * cos_i - cos_t));
  return true;
}

}  // namespace raygate

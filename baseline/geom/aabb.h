// Axis-aligned boxes for the `--accel bbox` control (one box per primitive, no hierarchy).
// The slab test is written to be conservative: it never rejects a ray that the exact primitive
// test would accept, so the bbox mode renders bit-identical images (docs/baseline.md).
#pragma once

#include <limits>

#include "geom/ray.h"
#include "geom/vec3.h"

namespace raygate {

struct Aabb {
  Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
  Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
};

inline void expand(Aabb& box, const Vec3& p) {
  box.lo = component_min(box.lo, p);
  box.hi = component_max(box.hi, p);
}

// Grows the box on every side by a margin relative to its size and position, so rounding in
// a primitive's hit point (grazing hits, flat boxes of planar polygons) stays inside it.
inline Aabb padded(const Aabb& box, double relative_margin) {
  const double magnitude = std::fmax(max_abs_component(box.lo), max_abs_component(box.hi));
  const double extent = max_abs_component(box.hi - box.lo);
  const double margin = relative_margin * (magnitude + extent);
  const Vec3 pad{margin, margin, margin};
  return {box.lo - pad, box.hi + pad};
}

// Per-ray data for the slab test, computed once per ray.
struct SlabRay {
  Vec3 origin;
  Vec3 inverse_direction;  // +-inf where a direction component is 0
};

inline SlabRay make_slab_ray(const Ray& ray) {
  return {ray.origin, {1.0 / ray.direction.x, 1.0 / ray.direction.y, 1.0 / ray.direction.z}};
}

// One axis of the slab test. A zero direction component gives an infinite inverse; the
// origin is then tested against the slab directly, avoiding 0 * inf = NaN.
inline bool clip_slab(double origin, double inverse_direction, double lo, double hi, double& t_near,
                      double& t_far) {
  if (std::isinf(inverse_direction)) return origin >= lo && origin <= hi;
  double t0 = (lo - origin) * inverse_direction;
  double t1 = (hi - origin) * inverse_direction;
  if (t0 > t1) {
    const double swap = t0;
    t0 = t1;
    t1 = swap;
  }
  if (t0 > t_near) t_near = t0;
  if (t1 < t_far) t_far = t1;
  return t_near <= t_far;
}

// True if the ray meets the box for some t in [t_min, t_max].
inline bool hits_box(const Aabb& box, const SlabRay& ray, double t_min, double t_max) {
  double t_near = t_min;
  double t_far = t_max;
  return clip_slab(ray.origin.x, ray.inverse_direction.x, box.lo.x, box.hi.x, t_near, t_far) &&
         clip_slab(ray.origin.y, ray.inverse_direction.y, box.lo.y, box.hi.y, t_near, t_far) &&
         clip_slab(ray.origin.z, ray.inverse_direction.z, box.lo.z, box.hi.z, t_near, t_far);
}

}  // namespace raygate

// What the shader needs to know about a hit: the point (re-projected onto the exact surface),
// the primitive's geometric normal, the shading normal and a coordinate scale for offsetting
// secondary-ray origins (docs/baseline.md, "Self-intersection").
#pragma once

#include "geom/ray.h"
#include "render/world.h"

namespace raygate::render {

struct SurfacePoint {
  Vec3 point;
  Vec3 geometric_normal;   // unit, the primitive's front side
  Vec3 shading_normal;     // unit, same hemisphere as geometric_normal
  double magnitude = 0.0;  // largest coordinate magnitude involved in computing `point`
  int material = 0;
};

SurfacePoint evaluate_surface(const World& world, const Ray& ray, const Hit& hit);

// Every primitive is two-sided: both normals are turned toward the incoming ray, and the
// geometric normal alone decides whether the ray arrives at the front (enters a transmitter).
struct Facing {
  bool entering = true;
  Vec3 geometric;  // unit, dot(geometric, incoming) <= 0
  Vec3 shading;    // unit, on the geometric normal's side
};

inline Facing face_toward(const SurfacePoint& s, const Vec3& incoming) {
  const bool entering = dot(s.geometric_normal, incoming) < 0.0;
  return entering ? Facing{true, s.geometric_normal, s.shading_normal}
                  : Facing{false, -s.geometric_normal, -s.shading_normal};
}

// Secondary rays start this far (relative to SurfacePoint::magnitude) off the surface along
// the geometric normal: about 10^7 times the rounding error of a re-projected hit point.
inline constexpr double kOffsetRelative = 1e-9;

inline double origin_offset(const SurfacePoint& s) {
  const double scale = std::fmax(max_abs_component(s.point), s.magnitude);
  return kOffsetRelative * scale;
}

}  // namespace raygate::render

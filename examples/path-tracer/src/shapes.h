// Ray-shape intersection and bounding boxes for the four NFF shapes. A ShapeRef names one shape
// of the scene, so the bounding volume hierarchy can hold every kind in one list.
#pragma once

#include <cstdint>
#include <vector>

#include "scene.h"

namespace nff {

enum class ShapeKind : std::uint8_t { sphere, cone, polygon, triangle };

struct ShapeRef {
  ShapeKind kind;
  std::uint32_t index;  // into the scene's vector of that kind
};

struct Box {
  Vec3 low{1e300, 1e300, 1e300}, high{-1e300, -1e300, -1e300};

  void grow(Vec3 p) { low = min(low, p), high = max(high, p); }
  void grow(const Box& b) { low = min(low, b.low), high = max(high, b.high); }
  Vec3 centre() const { return (low + high) * 0.5; }
};

// The nearest hit found so far. `normal` is the shading normal, not yet turned to face the ray.
struct Hit {
  double t = 1e300;
  Vec3 normal;
  int material = 0;
};

std::vector<ShapeRef> all_shapes(const Scene& scene);
Box bounds(const Scene& scene, ShapeRef shape);

// True, and `hit` updated, when the ray meets the shape at some t_min < t < hit.t.
bool intersect(const Scene& scene, ShapeRef shape, const Ray& ray, double t_min, Hit& hit);

}  // namespace nff

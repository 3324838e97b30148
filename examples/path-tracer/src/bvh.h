// A bounding volume hierarchy over every shape of the scene: boxes split at the median of the
// shapes' centres along the widest axis. It turns "test every shape" into "test the few shapes
// whose boxes the ray enters", which is what makes the big SPD scenes fast.
#pragma once

#include <cstdint>
#include <vector>

#include "shapes.h"

namespace nff {

class Bvh {
 public:
  explicit Bvh(const Scene& scene);

  // The nearest hit with t_min < t < hit.t; updates `hit` and returns true when there is one.
  bool closest(const Ray& ray, double t_min, Hit& hit) const;
  // True when anything lies between t_min and distance: a shadow ray's question. Any hit
  // answers it, so the search stops at the first one.
  bool occluded(const Ray& ray, double t_min, double distance) const;

  std::size_t node_count() const { return nodes_.size(); }

 private:
  struct Node {
    Box box;
    std::uint32_t first = 0;  // leaf: first shape in shapes_; interior: index of the right child
    std::uint32_t count = 0;  // shapes in a leaf; 0 for an interior node (left child = this + 1)
    int axis = 0;             // interior: the axis it was split on
  };

  std::uint32_t build(std::uint32_t begin, std::uint32_t end);
  template <class Visit>
  bool traverse(const Ray& ray, double t_min, const double& t_max, Visit&& visit) const;

  const Scene& scene_;
  std::vector<ShapeRef> shapes_;
  std::vector<Box> boxes_;  // boxes_[i] bounds shapes_[i] (kept in the same order while building)
  std::vector<Node> nodes_;
};

}  // namespace nff

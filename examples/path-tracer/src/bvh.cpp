#include "bvh.h"

#include <algorithm>
#include <numeric>

namespace nff {
namespace {

constexpr std::uint32_t kLeafShapes = 4;  // small leaves: a box test is cheaper than a shape test

// Does the ray enter the box between t_min and t_max? (The slab test.)
bool enters(const Box& box, const Ray& ray, Vec3 inverse_direction, double t_min, double t_max) {
  for (int axis = 0; axis < 3; ++axis) {
    double t0 = (box.low[axis] - ray.origin[axis]) * inverse_direction[axis];
    double t1 = (box.high[axis] - ray.origin[axis]) * inverse_direction[axis];
    if (t0 > t1) std::swap(t0, t1);
    t_min = std::max(t_min, t0);
    t_max = std::min(t_max, t1);
    if (t_min > t_max) return false;
  }
  return true;
}

}  // namespace

Bvh::Bvh(const Scene& scene) : scene_(scene), shapes_(all_shapes(scene)) {
  const Vec3 pad{1e-9, 1e-9, 1e-9};  // flat shapes get boxes with some thickness
  for (ShapeRef shape : shapes_) {
    Box box = bounds(scene, shape);
    box.low = box.low - pad, box.high = box.high + pad;
    boxes_.push_back(box);
  }
  nodes_.reserve(2 * shapes_.size());
  if (!shapes_.empty()) build(0, static_cast<std::uint32_t>(shapes_.size()));
}

std::uint32_t Bvh::build(std::uint32_t begin, std::uint32_t end) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Box box, centres;
  for (std::uint32_t i = begin; i < end; ++i) box.grow(boxes_[i]), centres.grow(boxes_[i].centre());
  nodes_[index].box = box;
  const Vec3 extent = centres.high - centres.low;
  const int axis =
      extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
  if (end - begin <= kLeafShapes || extent[axis] <= 0) {
    nodes_[index].first = begin, nodes_[index].count = end - begin;
    return index;
  }
  // Sort the range's (shape, box) pairs by centre along the axis, split at the median.
  std::vector<std::uint32_t> order(end - begin);
  std::iota(order.begin(), order.end(), begin);
  const std::uint32_t middle = (end - begin) / 2;
  std::nth_element(order.begin(), order.begin() + middle, order.end(),
                   [&](std::uint32_t a, std::uint32_t b) {
                     return boxes_[a].centre()[axis] < boxes_[b].centre()[axis];
                   });
  std::vector<ShapeRef> shapes;
  std::vector<Box> boxes;
  for (std::uint32_t i : order) shapes.push_back(shapes_[i]), boxes.push_back(boxes_[i]);
  std::copy(shapes.begin(), shapes.end(), shapes_.begin() + begin);
  std::copy(boxes.begin(), boxes.end(), boxes_.begin() + begin);
  nodes_[index].axis = axis;
  build(begin, begin + middle);
  nodes_[index].first = build(begin + middle, end);
  return index;
}

// Depth first, nearer child first. `visit` tests one shape and returns true to stop the search;
// t_max is read through a reference because a closest-hit search shrinks it as it goes.
template <class Visit>
bool Bvh::traverse(const Ray& ray, double t_min, const double& t_max, Visit&& visit) const {
  if (nodes_.empty()) return false;
  const Vec3 inverse{1 / ray.direction.x, 1 / ray.direction.y, 1 / ray.direction.z};
  std::uint32_t stack[64];
  int depth = 0;
  stack[depth++] = 0;
  bool found = false;
  while (depth > 0) {
    const Node& node = nodes_[stack[--depth]];
    if (!enters(node.box, ray, inverse, t_min, t_max)) continue;
    if (node.count > 0) {
      for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
        if (visit(shapes_[i])) {
          found = true;
          if (visit.stop_at_first) return true;
        }
      }
      continue;
    }
    const auto left = static_cast<std::uint32_t>(&node - nodes_.data()) + 1;
    const bool left_first = ray.direction[node.axis] >= 0;
    stack[depth++] = left_first ? node.first : left;  // pushed first, visited second
    stack[depth++] = left_first ? left : node.first;
  }
  return found;
}

namespace {

struct NearestVisit {
  const Scene& scene;
  const Ray& ray;
  double t_min;
  Hit& hit;
  static constexpr bool stop_at_first = false;
  bool operator()(ShapeRef shape) const { return intersect(scene, shape, ray, t_min, hit); }
};

struct AnyVisit {
  const Scene& scene;
  const Ray& ray;
  double t_min;
  Hit& probe;
  static constexpr bool stop_at_first = true;
  bool operator()(ShapeRef shape) const { return intersect(scene, shape, ray, t_min, probe); }
};

}  // namespace

bool Bvh::closest(const Ray& ray, double t_min, Hit& hit) const {
  return traverse(ray, t_min, hit.t, NearestVisit{scene_, ray, t_min, hit});
}

bool Bvh::occluded(const Ray& ray, double t_min, double distance) const {
  Hit probe;
  probe.t = distance;
  return traverse(ray, t_min, probe.t, AnyVisit{scene_, ray, t_min, probe});
}

}  // namespace nff

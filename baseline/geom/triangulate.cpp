// Ear-clipping triangulation of planar, possibly concave polygons (see triangulate.h).
// The gears' 144-gon faces (spd-spec.md §3.2) are the hard case in the SPD: deep notches
// whose reflex corners block most candidate ears.
#include "geom/triangulate.h"

#include <cmath>
#include <cstddef>
#include <utility>

namespace raygate {
namespace {

struct Point2 {
  double u = 0.0;
  double v = 0.0;
};

bool same(const Point2& a, const Point2& b) { return a.u == b.u && a.v == b.v; }

// Twice the signed area of (a, b, c): positive when counter-clockwise in (u, v).
double cross2(const Point2& a, const Point2& b, const Point2& c) {
  return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
}

// The axis along which the normal is largest: dropping it gives the largest projection, never
// degenerate for a polygon with area.
int dominant_axis(const Vec3& normal) {
  const double ax = std::fabs(normal.x);
  const double ay = std::fabs(normal.y);
  const double az = std::fabs(normal.z);
  if (ax >= ay && ax >= az) return 0;
  return ay >= az ? 1 : 2;
}

std::vector<Point2> project(const std::vector<Vec3>& vertices, int drop) {
  const int u_axis = drop == 0 ? 1 : 0;
  const int v_axis = drop == 2 ? 1 : 2;
  std::vector<Point2> points;
  points.reserve(vertices.size());
  for (const Vec3& p : vertices) points.push_back({p[u_axis], p[v_axis]});
  return points;
}

// The polygon as a ring of indices that shrinks as ears are cut off. `sign` is +1 when the
// projected polygon runs counter-clockwise and -1 otherwise, so "convex" means the same thing
// for both windings and the output keeps the input's order.
class EarClipper {
 public:
  EarClipper(std::vector<Point2> points, double sign)
      : points_(std::move(points)), sign_(sign), next_(points_.size()), prev_(points_.size()) {
    const int n = static_cast<int>(points_.size());
    for (int i = 0; i < n; ++i) {
      next_[i] = (i + 1) % n;
      prev_[i] = (i + n - 1) % n;
    }
    remaining_ = n;
  }

  std::vector<std::array<int, 3>> run() {
    std::vector<std::array<int, 3>> triangles;
    triangles.reserve(points_.size() - 2);
    int current = 0;
    // Every iteration removes one vertex, so this loop runs exactly n - 3 times.
    while (remaining_ > 3) {
      const int ear = find_ear(current);
      const double turn = turn_at(ear);
      // Only the last-resort choice for a non-simple ring can be inverted; dropping it keeps
      // every returned triangle facing the polygon's way.
      if (turn >= 0.0) triangles.push_back({prev_[ear], ear, next_[ear]});
      current = next_[ear];
      remove(ear);
    }
    if (turn_at(current) >= 0.0) triangles.push_back({prev_[current], current, next_[current]});
    return triangles;
  }

 private:
  // Orientation-corrected turn at vertex i: > 0 convex, 0 straight or spike, < 0 reflex.
  double turn_at(int i) const {
    return sign_ * cross2(points_[prev_[i]], points_[i], points_[next_[i]]);
  }

  // Strictly convex and no other ring vertex inside or on the triangle. Only vertices whose
  // turn is not convex can poke into an ear of a simple polygon, so only those are tested.
  bool is_ear(int i) const {
    if (turn_at(i) <= 0.0) return false;
    const Point2& a = points_[prev_[i]];
    const Point2& b = points_[i];
    const Point2& c = points_[next_[i]];
    for (int j = next_[next_[i]]; j != prev_[i]; j = next_[j]) {
      const Point2& p = points_[j];
      // Repeated positions (a ring that touches itself) share the ear's corners, not its area.
      if (same(p, a) || same(p, b) || same(p, c)) continue;
      if (turn_at(j) > 0.0) continue;
      if (sign_ * cross2(a, b, p) >= 0.0 && sign_ * cross2(b, c, p) >= 0.0 &&
          sign_ * cross2(c, a, p) >= 0.0) {
        return false;
      }
    }
    return true;
  }

  // The next vertex to cut, searching forward from `start`. Preference: a true ear; else a
  // vertex with no turn (collinear or repeated: its triangle has zero area); else, for a ring
  // that is not simple or lost to rounding, any convex vertex; else `start` itself.
  int find_ear(int start) const {
    int i = start;
    for (int k = 0; k < remaining_; ++k, i = next_[i]) {
      if (is_ear(i)) return i;
    }
    for (int k = 0; k < remaining_; ++k, i = next_[i]) {
      if (turn_at(i) == 0.0) return i;
    }
    for (int k = 0; k < remaining_; ++k, i = next_[i]) {
      if (turn_at(i) > 0.0) return i;
    }
    return start;
  }

  void remove(int i) {
    next_[prev_[i]] = next_[i];
    prev_[next_[i]] = prev_[i];
    --remaining_;
  }

  std::vector<Point2> points_;
  double sign_;
  std::vector<int> next_;
  std::vector<int> prev_;
  int remaining_ = 0;
};

}  // namespace

// Coordinates are taken relative to the first vertex so that polygons far from the origin do
// not lose their area to cancellation.
Vec3 polygon_area_normal(const std::vector<Vec3>& vertices) {
  Vec3 normal;
  if (vertices.size() < 3) return normal;
  const Vec3 origin = vertices.front();
  const std::size_t n = vertices.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a = vertices[i] - origin;
    const Vec3 b = vertices[(i + 1) % n] - origin;
    normal.x += (a.y - b.y) * (a.z + b.z);
    normal.y += (a.z - b.z) * (a.x + b.x);
    normal.z += (a.x - b.x) * (a.y + b.y);
  }
  return normal;
}

std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Vec3>& vertices) {
  if (vertices.size() < 3) return {};
  const Vec3 normal = polygon_area_normal(vertices);
  if (!is_finite(normal) || dot(normal, normal) == 0.0) return {};
  const int drop = dominant_axis(normal);
  // Newell's components are the areas projected onto (y, z), (z, x) and (x, y). Dropping y
  // projects onto (x, z), the mirror of (z, x), hence the flip.
  const double component = drop == 0 ? normal.x : (drop == 1 ? -normal.y : normal.z);
  const double sign = component > 0.0 ? 1.0 : -1.0;
  return EarClipper(project(vertices, drop), sign).run();
}

}  // namespace raygate

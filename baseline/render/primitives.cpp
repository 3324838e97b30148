// Building the tracer's primitives from NFF data, and their bounding boxes.
#include "render/primitives.h"

#include <cmath>

#include "geom/ray.h"

namespace raygate::render {
namespace {

bool is_usable_length(double length) { return std::isfinite(length) && length > 0.0; }

// Newell's method: robust for concave outlines and near-collinear first vertices; its
// direction follows the winding (counter-clockwise seen from the front).
Vec3 newell_normal(const std::vector<Vec3>& vertices) {
  Vec3 sum;
  const std::size_t count = vertices.size();
  for (std::size_t i = 0; i < count; ++i) {
    const Vec3& a = vertices[i];
    const Vec3& b = vertices[(i + 1) % count];
    sum.x += (a.y - b.y) * (a.z + b.z);
    sum.y += (a.z - b.z) * (a.x + b.x);
    sum.z += (a.x - b.x) * (a.y + b.y);
  }
  return sum;
}

// The axis of the normal's largest component; projecting it away keeps the outline's area.
int dominant_axis(const Vec3& n) {
  const double ax = std::fabs(n.x);
  const double ay = std::fabs(n.y);
  const double az = std::fabs(n.z);
  if (ax >= ay && ax >= az) return 0;
  return ay >= az ? 1 : 2;
}

// Half-extent of a circle of radius r, perpendicular to the unit axis, along coordinate i.
Vec3 rim_extent(const Vec3& axis, double radius) {
  return {radius * std::sqrt(std::fmax(0.0, 1.0 - axis.x * axis.x)),
          radius * std::sqrt(std::fmax(0.0, 1.0 - axis.y * axis.y)),
          radius * std::sqrt(std::fmax(0.0, 1.0 - axis.z * axis.z))};
}

}  // namespace

bool make_sphere(const Vec3& center, double radius, int material, SpherePrim& out) {
  const double r = std::fabs(radius);
  if (!is_usable_length(r) || !is_finite(center)) return false;
  out = {center, r, r * r, radius < 0.0 ? -1.0 : 1.0, material};
  return true;
}

bool make_cone(const Vec3& base, double base_radius, const Vec3& apex, double apex_radius,
               int material, ConePrim& out) {
  const Vec3 span = apex - base;
  const double height = length(span);
  const double rb = std::fabs(base_radius);
  const double ra = std::fabs(apex_radius);
  if (!is_usable_length(height) || !std::isfinite(rb) || !std::isfinite(ra) ||
      (rb == 0.0 && ra == 0.0)) {
    return false;
  }
  out.base = base;
  out.axis = span / height;
  out.height = height;
  out.base_radius = rb;
  out.slope = (ra - rb) / height;
  out.orientation = (base_radius < 0.0 || apex_radius < 0.0) ? -1.0 : 1.0;
  out.magnitude = std::fmax(max_abs_component(base), max_abs_component(apex)) + std::fmax(rb, ra);
  out.material = material;
  return true;
}

bool make_polygon(const std::vector<Vec3>& vertices, int material, PolygonPrim& out,
                  std::vector<Point2>& points) {
  if (vertices.size() < 3) return false;
  const Vec3 n = newell_normal(vertices);
  const double n_length = length(n);
  if (!is_usable_length(n_length)) return false;
  out.normal = n / n_length;
  out.plane_offset = dot(out.normal, vertices[0]);
  const int drop = dominant_axis(out.normal);
  out.u_axis = static_cast<std::uint8_t>((drop + 1) % 3);
  out.v_axis = static_cast<std::uint8_t>((drop + 2) % 3);
  out.first_point = static_cast<int>(points.size());
  out.point_count = static_cast<int>(vertices.size());
  out.magnitude = 0.0;
  for (const Vec3& v : vertices) {
    points.push_back({v[out.u_axis], v[out.v_axis]});
    out.magnitude = std::fmax(out.magnitude, max_abs_component(v));
  }
  out.material = material;
  return true;
}

bool make_triangle(const Vec3 (&vertices)[3], const Vec3 (&normals)[3], int material,
                   TrianglePrim& out) {
  out.v0 = vertices[0];
  out.edge1 = vertices[1] - vertices[0];
  out.edge2 = vertices[2] - vertices[0];
  const Vec3 n = cross(out.edge1, out.edge2);
  const double n_length = length(n);
  if (!is_usable_length(n_length)) return false;
  out.normal = n / n_length;
  out.n0 = normals[0];
  out.n1 = normals[1];
  out.n2 = normals[2];
  out.magnitude =
      std::fmax(max_abs_component(vertices[0]),
                std::fmax(max_abs_component(vertices[1]), max_abs_component(vertices[2])));
  out.material = material;
  return true;
}

Aabb bounds(const SpherePrim& sphere) {
  const Vec3 r{sphere.radius, sphere.radius, sphere.radius};
  return {sphere.center - r, sphere.center + r};
}

Aabb bounds(const ConePrim& cone) {
  const Vec3 apex = cone.base + cone.axis * cone.height;
  const double apex_radius = cone.base_radius + cone.slope * cone.height;
  const Vec3 base_extent = rim_extent(cone.axis, cone.base_radius);
  const Vec3 apex_extent = rim_extent(cone.axis, std::fmax(0.0, apex_radius));
  Aabb box;
  expand(box, cone.base - base_extent);
  expand(box, cone.base + base_extent);
  expand(box, apex - apex_extent);
  expand(box, apex + apex_extent);
  return box;
}

Aabb bounds(const std::vector<Vec3>& polygon_vertices) {
  Aabb box;
  for (const Vec3& v : polygon_vertices) expand(box, v);
  return box;
}

Aabb bounds(const TrianglePrim& triangle) {
  Aabb box;
  expand(box, triangle.v0);
  expand(box, triangle.v0 + triangle.edge1);
  expand(box, triangle.v0 + triangle.edge2);
  return box;
}

}  // namespace raygate::render

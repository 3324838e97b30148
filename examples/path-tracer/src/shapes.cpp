#include "shapes.h"

#include <cmath>

namespace nff {
namespace {

// The two roots of a t^2 + b t + c = 0 in increasing order; false when there are none.
// Uses the cancellation-free form q = -(b + sign(b) sqrt(disc)) / 2.
bool solve_quadratic(double a, double b, double c, double& t0, double& t1) {
  if (std::fabs(a) < 1e-14) {  // a ray parallel to a cone's side: one linear root
    if (b == 0) return false;
    t0 = t1 = -c / b;
    return true;
  }
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return false;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  t0 = q / a;
  t1 = q != 0 ? c / q : t0;
  if (t0 > t1) std::swap(t0, t1);
  return true;
}

bool hit_sphere(const Sphere& s, const Ray& ray, double t_min, Hit& hit) {
  const Vec3 oc = ray.origin - s.centre;
  double t0, t1;
  if (!solve_quadratic(1, 2 * dot(oc, ray.direction), dot(oc, oc) - s.radius * s.radius, t0, t1)) {
    return false;
  }
  const double t = t0 > t_min ? t0 : t1;
  if (t <= t_min || t >= hit.t) return false;
  hit = {t, (ray.at(t) - s.centre) * (1 / s.radius), s.material};
  return true;
}

// Points p with |p_perp|^2 = (r(s))^2, s the distance along the axis from the base and r(s)
// linear from base_radius to apex_radius; only 0 <= s <= height counts (no mirrored nappe).
bool hit_cone(const Cone& cone, const Ray& ray, double t_min, Hit& hit) {
  const Vec3 axis_full = cone.apex - cone.base;
  const double height = length(axis_full);
  if (height == 0) return false;
  const Vec3 axis = axis_full * (1 / height);
  const double slope = (cone.apex_radius - cone.base_radius) / height;
  const Vec3 w = ray.origin - cone.base;
  const double w_a = dot(w, axis), d_a = dot(ray.direction, axis);
  const Vec3 w_perp = w - axis * w_a, d_perp = ray.direction - axis * d_a;
  const double r_origin = cone.base_radius + slope * w_a;  // radius at the origin's axis position
  const double a = dot(d_perp, d_perp) - slope * slope * d_a * d_a;
  const double b = 2 * (dot(w_perp, d_perp) - slope * r_origin * d_a);
  const double c = dot(w_perp, w_perp) - r_origin * r_origin;
  double roots[2];
  if (!solve_quadratic(a, b, c, roots[0], roots[1])) return false;
  for (double t : roots) {
    if (t <= t_min || t >= hit.t) continue;
    const Vec3 q = ray.at(t) - cone.base;
    const double s = dot(q, axis);
    if (s < 0 || s > height) continue;
    const double radius = cone.base_radius + slope * s;
    hit = {t, normalize((q - axis * s) - axis * (radius * slope)), cone.material};
    return true;
  }
  return false;
}

// The even-odd rule on the outline projected onto the plane that drops the normal's largest axis.
bool inside_outline(const Polygon& polygon, Vec3 p) {
  const Vec3 n = polygon.normal;
  const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  const int u = ax >= ay && ax >= az ? 1 : 0;
  const int v = ax >= ay && ax >= az ? 2 : (ay >= az ? 2 : 1);
  bool inside = false;
  const std::size_t count = polygon.vertices.size();
  for (std::size_t i = 0, j = count - 1; i < count; j = i++) {
    const Vec3 a = polygon.vertices[i], b = polygon.vertices[j];
    if ((a[v] > p[v]) != (b[v] > p[v]) &&
        p[u] < (b[u] - a[u]) * (p[v] - a[v]) / (b[v] - a[v]) + a[u]) {
      inside = !inside;
    }
  }
  return inside;
}

bool hit_polygon(const Polygon& polygon, const Ray& ray, double t_min, Hit& hit) {
  const double facing = dot(polygon.normal, ray.direction);
  if (facing == 0) return false;
  const double t = dot(polygon.normal, polygon.vertices[0] - ray.origin) / facing;
  if (t <= t_min || t >= hit.t || !inside_outline(polygon, ray.at(t))) return false;
  hit = {t, polygon.normal, polygon.material};
  return true;
}

// Moller-Trumbore, both sides; the normal blends the vertex normals.
bool hit_triangle(const Triangle& tri, const Ray& ray, double t_min, Hit& hit) {
  const Vec3 e1 = tri.b - tri.a, e2 = tri.c - tri.a, p = cross(ray.direction, e2);
  const double det = dot(e1, p);
  if (std::fabs(det) < 1e-14) return false;
  const double inv = 1 / det;
  const Vec3 q = ray.origin - tri.a;
  const double b1 = dot(q, p) * inv;
  if (b1 < 0 || b1 > 1) return false;
  const Vec3 r = cross(q, e1);
  const double b2 = dot(ray.direction, r) * inv;
  if (b2 < 0 || b1 + b2 > 1) return false;
  const double t = dot(e2, r) * inv;
  if (t <= t_min || t >= hit.t) return false;
  const Vec3 blend = tri.normal_a * (1 - b1 - b2) + tri.normal_b * b1 + tri.normal_c * b2;
  hit = {t, length(blend) > 0 ? normalize(blend) : normalize(cross(e1, e2)), tri.material};
  return true;
}

}  // namespace

std::vector<ShapeRef> all_shapes(const Scene& scene) {
  std::vector<ShapeRef> shapes;
  auto add = [&shapes](ShapeKind kind, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) shapes.push_back({kind, static_cast<std::uint32_t>(i)});
  };
  add(ShapeKind::sphere, scene.spheres.size());
  add(ShapeKind::cone, scene.cones.size());
  add(ShapeKind::polygon, scene.polygons.size());
  add(ShapeKind::triangle, scene.triangles.size());
  return shapes;
}

Box bounds(const Scene& scene, ShapeRef shape) {
  Box box;
  switch (shape.kind) {
    case ShapeKind::sphere: {
      const Sphere& s = scene.spheres[shape.index];
      const Vec3 r{s.radius, s.radius, s.radius};
      box.grow(s.centre - r), box.grow(s.centre + r);
      break;
    }
    case ShapeKind::cone: {  // the boxes of both end discs, taken as balls: loose but safe
      const Cone& c = scene.cones[shape.index];
      const Vec3 rb{c.base_radius, c.base_radius, c.base_radius};
      const Vec3 ra{c.apex_radius, c.apex_radius, c.apex_radius};
      box.grow(c.base - rb), box.grow(c.base + rb), box.grow(c.apex - ra), box.grow(c.apex + ra);
      break;
    }
    case ShapeKind::polygon:
      for (Vec3 v : scene.polygons[shape.index].vertices) box.grow(v);
      break;
    case ShapeKind::triangle: {
      const Triangle& t = scene.triangles[shape.index];
      box.grow(t.a), box.grow(t.b), box.grow(t.c);
      break;
    }
  }
  return box;
}

bool intersect(const Scene& scene, ShapeRef shape, const Ray& ray, double t_min, Hit& hit) {
  switch (shape.kind) {
    case ShapeKind::sphere: return hit_sphere(scene.spheres[shape.index], ray, t_min, hit);
    case ShapeKind::cone: return hit_cone(scene.cones[shape.index], ray, t_min, hit);
    case ShapeKind::polygon: return hit_polygon(scene.polygons[shape.index], ray, t_min, hit);
    case ShapeKind::triangle: return hit_triangle(scene.triangles[shape.index], ray, t_min, hit);
  }
  return false;
}

}  // namespace nff

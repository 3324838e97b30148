// Exact ray-primitive tests. Every test accepts a hit only for t_min < t < t_max and reports
// the nearest such t; `none` and `bbox` both call exactly these functions, so both modes see
// the same bits. Inline: they sit in the innermost loop.
#pragma once

#include <cmath>
#include <vector>

#include "geom/ray.h"
#include "render/primitives.h"

namespace raygate::render {

// What a test reports: the distance, plus barycentrics for triangles.
struct PrimHit {
  double t = 0.0;
  double b1 = 0.0;
  double b2 = 0.0;
};

// Picks the nearer of two roots inside (t_min, t_max). NaN or infinite roots never qualify.
inline bool pick_root(double r0, double r1, double t_min, double t_max, double& t) {
  if (r1 < r0) {
    const double swap = r0;
    r0 = r1;
    r1 = swap;
  }
  if (r0 > t_min && r0 < t_max) {
    t = r0;
    return true;
  }
  if (r1 > t_min && r1 < t_max) {
    t = r1;
    return true;
  }
  return false;
}

// Sphere: the discriminant is formed from the ray's perpendicular offset from the centre
// (r^2 - |oc - b d|^2) rather than b^2 - c, which cancels badly for distant origins; the
// roots come from the cancellation-free pair q and c/q.
inline bool intersect(const SpherePrim& s, const Ray& ray, double t_min, double t_max,
                      PrimHit& hit) {
  const Vec3 oc = ray.origin - s.center;
  const double b = dot(oc, ray.direction);
  const Vec3 perpendicular = oc - ray.direction * b;
  const double h = s.radius_squared - dot(perpendicular, perpendicular);
  if (h < 0.0) return false;
  const double c = dot(oc, oc) - s.radius_squared;
  const double q = -b - std::copysign(std::sqrt(h), b);
  if (q == 0.0) return false;  // origin on the surface, tangent ray: both roots are 0
  return pick_root(q, c / q, t_min, t_max, hit.t);
}

// Open cone or cylinder: |w_perp + t d_perp|^2 = (r0 + k (w.a + t d.a))^2, a quadratic
// A t^2 + 2 B t + C = 0, solved with the stable q form; A == 0 (a ray parallel to a side
// line) then leaves the single linear root C/q. Roots outside the height range are rejected.
inline bool intersect(const ConePrim& c, const Ray& ray, double t_min, double t_max, PrimHit& hit) {
  const Vec3 w = ray.origin - c.base;
  const double w_axial = dot(w, c.axis);
  const double d_axial = dot(ray.direction, c.axis);
  const Vec3 w_perp = w - c.axis * w_axial;
  const Vec3 d_perp = ray.direction - c.axis * d_axial;
  const double r_origin = c.base_radius + c.slope * w_axial;
  const double r_rate = c.slope * d_axial;
  const double qa = dot(d_perp, d_perp) - r_rate * r_rate;
  const double qb = dot(w_perp, d_perp) - r_origin * r_rate;
  const double qc = dot(w_perp, w_perp) - r_origin * r_origin;
  const double discriminant = qb * qb - qa * qc;
  if (discriminant < 0.0) return false;
  const double q = -(qb + std::copysign(std::sqrt(discriminant), qb));
  if (q == 0.0) return false;
  double roots[2] = {qa != 0.0 ? q / qa : NAN, qc / q};
  if (roots[1] < roots[0]) {
    const double swap = roots[0];
    roots[0] = roots[1];
    roots[1] = swap;
  }
  for (const double t : roots) {
    if (!(t > t_min && t < t_max)) continue;
    const double h = w_axial + t * d_axial;
    if (h >= 0.0 && h <= c.height) {
      hit.t = t;
      return true;
    }
  }
  return false;
}

inline double component(const Vec3& v, int axis) {
  return axis == 0 ? v.x : (axis == 1 ? v.y : v.z);
}

// Even-odd rule: count outline edges crossed by the +u half-line from (u, v). The half-open
// comparison (a.v > v) != (b.v > v) counts a vertex on the line once, never twice.
inline bool inside_outline(const Point2* points, int count, double u, double v) {
  bool inside = false;
  for (int i = 0, j = count - 1; i < count; j = i++) {
    const Point2& a = points[i];
    const Point2& b = points[j];
    if ((a.v > v) != (b.v > v)) {
      const double u_cross = a.u + (v - a.v) * (b.u - a.u) / (b.v - a.v);
      if (u < u_cross) inside = !inside;
    }
  }
  return inside;
}

inline bool intersect(const PolygonPrim& p, const std::vector<Point2>& points, const Ray& ray,
                      double t_min, double t_max, PrimHit& hit) {
  const double denominator = dot(p.normal, ray.direction);
  if (denominator == 0.0) return false;  // parallel to the plane
  const double t = (p.plane_offset - dot(p.normal, ray.origin)) / denominator;
  if (!(t > t_min && t < t_max)) return false;
  const Vec3 at = point_at(ray, t);
  if (!inside_outline(points.data() + p.first_point, p.point_count, component(at, p.u_axis),
                      component(at, p.v_axis))) {
    return false;
  }
  hit.t = t;
  return true;
}

// Moller-Trumbore, two-sided (no culling on the sign of the determinant).
inline bool intersect(const TrianglePrim& tri, const Ray& ray, double t_min, double t_max,
                      PrimHit& hit) {
  const Vec3 p = cross(ray.direction, tri.edge2);
  const double determinant = dot(tri.edge1, p);
  if (determinant == 0.0) return false;
  const double inverse = 1.0 / determinant;
  const Vec3 s = ray.origin - tri.v0;
  const double b1 = dot(s, p) * inverse;
  if (b1 < 0.0 || b1 > 1.0) return false;
  const Vec3 q = cross(s, tri.edge1);
  const double b2 = dot(ray.direction, q) * inverse;
  if (b2 < 0.0 || b1 + b2 > 1.0) return false;
  const double t = dot(tri.edge2, q) * inverse;
  if (!(t > t_min && t < t_max)) return false;
  hit = {t, b1, b2};
  return true;
}

}  // namespace raygate::render

// Hit points and normals per primitive kind. Each hit point is moved back onto the exact
// surface (radially for spheres and cones, along the normal for planes, by barycentrics for
// triangles), so its error depends on the primitive's coordinates, not on how far the ray
// travelled; that is what makes a fixed relative origin offset sufficient.
#include "render/surface.h"

#include <cmath>

namespace raygate::render {
namespace {

SurfacePoint sphere_surface(const SpherePrim& s, const Ray& ray, double t) {
  const Vec3 outward = normalize(point_at(ray, t) - s.center);
  SurfacePoint out;
  out.point = s.center + outward * s.radius;
  out.geometric_normal = outward * s.orientation;
  out.shading_normal = out.geometric_normal;
  out.magnitude = max_abs_component(s.center) + s.radius;
  return out;
}

SurfacePoint cone_surface(const ConePrim& c, const Ray& ray, double t) {
  const Vec3 relative = point_at(ray, t) - c.base;
  const double h = dot(relative, c.axis);
  const Vec3 radial = relative - c.axis * h;
  const double radial_length = length(radial);
  const double radius = c.base_radius + c.slope * h;
  SurfacePoint out;
  if (radial_length > 0.0) {
    const Vec3 radial_unit = radial / radial_length;
    out.point = c.base + c.axis * h + radial_unit * radius;
    // Gradient of |radial|^2 - radius(h)^2, divided by 2 radius.
    out.geometric_normal = normalize(radial_unit - c.axis * c.slope) * c.orientation;
  } else {
    // Exactly on the axis (a cone's tip): any normal is as good; take the axis.
    out.point = c.base + c.axis * h;
    out.geometric_normal = c.axis * c.orientation;
  }
  out.shading_normal = out.geometric_normal;
  out.magnitude = c.magnitude;
  return out;
}

SurfacePoint polygon_surface(const PolygonPrim& p, const Ray& ray, double t) {
  const Vec3 at = point_at(ray, t);
  SurfacePoint out;
  out.point = at - p.normal * (dot(p.normal, at) - p.plane_offset);
  out.geometric_normal = p.normal;
  out.shading_normal = p.normal;
  out.magnitude = p.magnitude;
  return out;
}

// Smooth shading: the barycentric blend of the vertex normals, normalized, turned into the
// geometric normal's hemisphere so the front/back decision is the geometric one.
SurfacePoint triangle_surface(const TrianglePrim& tri, double b1, double b2) {
  SurfacePoint out;
  out.point = tri.v0 + tri.edge1 * b1 + tri.edge2 * b2;
  out.geometric_normal = tri.normal;
  const Vec3 blend = tri.n0 * (1.0 - b1 - b2) + tri.n1 * b1 + tri.n2 * b2;
  const double blend_length = length(blend);
  if (std::isfinite(blend_length) && blend_length > 0.0) {
    const Vec3 n = blend / blend_length;
    out.shading_normal = dot(n, tri.normal) < 0.0 ? -n : n;
  } else {
    out.shading_normal = tri.normal;
  }
  out.magnitude = tri.magnitude;
  return out;
}

}  // namespace

SurfacePoint evaluate_surface(const World& world, const Ray& ray, const Hit& hit) {
  SurfacePoint out;
  switch (hit.kind) {
    case PrimKind::sphere: {
      const SpherePrim& s = world.spheres[hit.index];
      out = sphere_surface(s, ray, hit.t);
      out.material = s.material;
      break;
    }
    case PrimKind::cone: {
      const ConePrim& c = world.cones[hit.index];
      out = cone_surface(c, ray, hit.t);
      out.material = c.material;
      break;
    }
    case PrimKind::polygon: {
      const PolygonPrim& p = world.polygons[hit.index];
      out = polygon_surface(p, ray, hit.t);
      out.material = p.material;
      break;
    }
    case PrimKind::triangle: {
      const TrianglePrim& tri = world.triangles[hit.index];
      out = triangle_surface(tri, hit.b1, hit.b2);
      out.material = tri.material;
      break;
    }
  }
  return out;
}

}  // namespace raygate::render

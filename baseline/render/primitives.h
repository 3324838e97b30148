// The tracer's primitives: NFF objects turned once, before rendering, into the data their
// intersection tests need (unit axes, plane equations, projected polygon outlines, edges).
// Plain structs, one array per kind: the hot loops call non-virtual, inlinable tests.
#pragma once

#include <cstdint>
#include <vector>

#include "geom/aabb.h"
#include "geom/vec3.h"

namespace raygate::render {

struct SpherePrim {
  Vec3 center;
  double radius = 0.0;  // |r| from the file
  double radius_squared = 0.0;
  double orientation = 1.0;  // -1 for NFF's negative (inside-visible) radius: normal inward
  int material = 0;
};

// Open truncated cone (no caps): radius(h) = base_radius + slope * h for h in [0, height]
// along the unit axis from the base centre.
struct ConePrim {
  Vec3 base;
  Vec3 axis;  // unit, base -> apex
  double height = 0.0;
  double base_radius = 0.0;  // |r| from the file
  double slope = 0.0;        // (apex_radius - base_radius) / height
  double orientation = 1.0;  // -1 when the file's radii are negative: normal inward
  double magnitude = 0.0;    // coordinate scale of its data, for hit-point offsets
  int material = 0;
};

// A planar, possibly concave polygon, tested by a plane hit and an even-odd crossing test on
// its outline projected onto the coordinate plane that drops the normal's largest component.
struct PolygonPrim {
  Vec3 normal;                // unit, front side per the vertex winding (Newell's method)
  double plane_offset = 0.0;  // dot(normal, any vertex)
  std::uint8_t u_axis = 0;    // projection axes
  std::uint8_t v_axis = 1;
  int first_point = 0;  // into World::polygon_points
  int point_count = 0;
  double magnitude = 0.0;
  int material = 0;
};

struct Point2 {
  double u = 0.0;
  double v = 0.0;
};

// A triangle of a `pp` patch, with vertex normals for smooth shading.
struct TrianglePrim {
  Vec3 v0;
  Vec3 edge1;       // v1 - v0
  Vec3 edge2;       // v2 - v0
  Vec3 normal;      // unit geometric normal, cross(edge1, edge2)
  Vec3 n0, n1, n2;  // vertex normals as written
  double magnitude = 0.0;
  int material = 0;
};

// Builders. Each returns false (and adds nothing) for a degenerate primitive that no ray can
// hit: zero radius sphere, zero-length or zero-radius cone, zero-area polygon or triangle.
bool make_sphere(const Vec3& center, double radius, int material, SpherePrim& out);
bool make_cone(const Vec3& base, double base_radius, const Vec3& apex, double apex_radius,
               int material, ConePrim& out);
// Appends the projected outline to `points`.
bool make_polygon(const std::vector<Vec3>& vertices, int material, PolygonPrim& out,
                  std::vector<Point2>& points);
bool make_triangle(const Vec3 (&vertices)[3], const Vec3 (&normals)[3], int material,
                   TrianglePrim& out);

// Bounding boxes (exact, before padding) for the bbox control.
Aabb bounds(const SpherePrim& sphere);
Aabb bounds(const ConePrim& cone);
Aabb bounds(const std::vector<Vec3>& polygon_vertices);
Aabb bounds(const TrianglePrim& triangle);

}  // namespace raygate::render

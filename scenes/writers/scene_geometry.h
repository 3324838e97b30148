// Geometry the scene writers share: the baseline's camera basis, the lights' intensity, and
// primitives turned into triangle meshes (spheres and cones tessellated, polygons and patches
// split by the ear-clipping triangulator). Internal to raygate_writers.
#pragma once

#include <array>
#include <cstddef>
#include <vector>

#include "geom/vec3.h"
#include "nff/scene.h"

namespace raygate::writers {

// The camera exactly as raygate-baseline builds it (docs/baseline.md "Camera").
struct CameraBasis {
  Vec3 forward;              // unit, from -> at
  Vec3 up;                   // unit: `up` with its forward component removed
  Vec3 right;                // unit, forward x up: the image's right in the right-handed NFF scene
  double half_width = 0.0;   // tan(angle / 2): half the image plane's width at distance 1
  double half_height = 0.0;  // half_width * height / width (square pixels)
};

// Throws std::invalid_argument for a view the baseline rejects.
CameraBasis camera_basis(const nff::View& view);

// NFF lights carry no intensity; the SPD exporters and the baseline use 1/sqrt(n) each.
double light_intensity(std::size_t light_count);

// An orthonormal, right-handed frame (u x v = w) around a unit axis w.
struct Frame {
  Vec3 u;
  Vec3 v;
  Vec3 w;
};
Frame frame_around(const Vec3& unit_axis);

// Primitives no ray can hit; the baseline drops them at load time.
bool is_degenerate(const nff::Sphere& sphere);
bool is_degenerate(const nff::Cone& cone);

// Triangles with counter-clockwise winding seen from the front (outside, for spheres and cones).
struct Mesh {
  std::vector<Vec3> positions;
  std::vector<Vec3> normals;  // empty, or one unit normal per position
  std::vector<std::array<int, 3>> triangles;
};

// A UV sphere: `segments` around its z axis, segments/2 bands from pole to pole, exact normals.
Mesh sphere_mesh(const nff::Sphere& sphere, int segments);
// The open cone's side: `segments` quads (a triangle where a rim has radius 0), exact normals.
Mesh cone_mesh(const nff::Cone& cone, int segments);
// Ear clipping (baseline/geom/triangulate.h), zero-area triangles dropped; none without area.
Mesh polygon_mesh(const nff::Polygon& polygon);
// As polygon_mesh, keeping the patch's vertex normals.
Mesh patch_mesh(const nff::Patch& patch);

// Throws std::invalid_argument unless 3 <= segments <= 1024.
void check_segments(int segments);

}  // namespace raygate::writers

// Splitting planar, possibly concave polygons (the gears' 144-gons) into triangles.
// Used where a consumer only takes triangles: patches with more than 3 vertices in the tracer,
// and the POV-Ray/OBJ/pbrt scene writers.
#pragma once

#include <array>
#include <vector>

#include "geom/vec3.h"

namespace raygate {

// Ear clipping on the polygon projected onto the plane that drops the largest component of
// its normal (Newell's method). Returns n-2 index triples into `vertices`, each keeping the
// polygon's winding. Collinear or repeated vertices are tolerated; a polygon that is not
// simple may yield fewer triangles, never indices out of range. A polygon without area (all
// vertices collinear or coincident, or non-finite) yields none.
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Vec3>& vertices);

// Newell's normal of a polygon: perpendicular to its plane, on the side from which the vertices
// run counter-clockwise, with a length of twice its area. Zero for fewer than 3 vertices or a
// polygon without area. Robust for non-planar input and polygons far from the origin.
Vec3 polygon_area_normal(const std::vector<Vec3>& vertices);

}  // namespace raygate

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
// simple may yield fewer triangles, never indices out of range.
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Vec3>& vertices);

}  // namespace raygate

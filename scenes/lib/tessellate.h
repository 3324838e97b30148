// Tessellation of curved primitives into smooth triangles (spd-spec.md §4), for the
// tessellated output mode and for primitives NFF cannot hold (tori, discs).
#pragma once

#include <array>
#include <vector>

#include "geom/vec3.h"

namespace raygate::scenes {

struct PatchTriangle {
  std::array<Vec3, 3> vertices;
  std::array<Vec3, 3> normals;
};

// 12·res² triangles on a cube-projected grid.
std::vector<PatchTriangle> tessellate_sphere(const Vec3& center, double radius, int res);
// 8·res triangles (4·res angular steps).
std::vector<PatchTriangle> tessellate_cone(const Vec3& base, double base_radius,
                                           const Vec3& apex, double apex_radius, int res);

}  // namespace raygate::scenes

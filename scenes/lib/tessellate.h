// Tessellation of curved primitives into smooth triangles (spd-spec.md §4), for the
// tessellated output mode and for primitives NFF cannot hold (tori, discs). Every function
// follows the SPD library's construction and emission order, so the triangles come out in the
// same order (and, where §2.3's evaluation rules are given, with the same bits).
#pragma once

#include <array>
#include <vector>

#include "geom/vec3.h"
#include "lib/matrix.h"

namespace raygate::scenes {

struct PatchTriangle {
  std::array<Vec3, 3> vertices;
  std::array<Vec3, 3> normals;
};

// A flat quad (as the disc emits it); NffWriter::polygon() merges repeated corners.
using Quad = std::array<Vec3, 4>;

// 12·res² triangles on a cube-projected grid.
std::vector<PatchTriangle> tessellate_sphere(const Vec3& center, double radius, int res);
// 8·res triangles (4·res angular steps).
std::vector<PatchTriangle> tessellate_cone(const Vec3& base, double base_radius, const Vec3& apex,
                                           double apex_radius, int res);

// The frame of tori and discs (§4): the rotation taking +z to `unit_normal` (about
// (−n_y, n_x, 0) by acos(n_z), or about +x when |n_z| = 1), then a translation to `center`.
Matrix4 canonical_frame(const Vec3& center, const Vec3& unit_normal);

// 32·res_u·res_v triangles: 4·res_u steps around the major circle, 4·res_v around the tube.
std::vector<PatchTriangle> tessellate_torus(const Vec3& center, const Vec3& unit_normal,
                                            double major_radius, double minor_radius, int res_u,
                                            int res_v);

// 4·res quads, one ring from inner_radius to outer_radius. With inner_radius 0 the two inner
// corners coincide, so the writer's clean-up turns each quad into a triangle (§1.5).
std::vector<Quad> tessellate_disc(const Vec3& center, const Vec3& unit_normal, double inner_radius,
                                  double outer_radius, int res);

}  // namespace raygate::scenes

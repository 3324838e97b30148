// Tessellation of spheres, cones, tori and discs as the SPD library does it (spd-spec.md §4).
// Evaluation orders follow §2.3: rotations go through the row-vector matrices of lib/matrix.h,
// normalize() divides by the length, and angles are stepped exactly as §4 says.
#include "lib/tessellate.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace raygate::scenes {
namespace {

constexpr double kPi = std::numbers::pi;

void require_resolution(int res, const char* what) {
  if (res < 1) throw std::invalid_argument(std::string(what) + ": resolution must be at least 1");
}

// Centre + r·unit, component by component (the sphere's vertex, §4 step 3).
Vec3 along(const Vec3& center, double radius, const Vec3& unit) {
  return {center.x + radius * unit.x, center.y + radius * unit.y, center.z + radius * unit.z};
}

using Grid = std::vector<std::vector<Vec3>>;

// The +Z cube face as unit points (§4 sphere step 1): x_axis[u] × y_axis[v], normalised.
Grid sphere_face_grid(int res) {
  Grid grid(res + 1, std::vector<Vec3>(res + 1));
  for (int u = 0; u <= res; ++u) {
    const double angle_u = (kPi / 4.0) * (2.0 * u / res - 1.0);
    const Vec3 x_axis = transform_vector({1.0, 0.0, 0.0}, Matrix4::rotate_y(angle_u));
    for (int v = 0; v <= res; ++v) {
      const double angle_v = (kPi / 4.0) * (2.0 * v / res - 1.0);
      const Vec3 y_axis = transform_vector({0.0, 1.0, 0.0}, Matrix4::rotate_x(angle_v));
      grid[u][v] = normalize(cross(x_axis, y_axis));
    }
  }
  return grid;
}

// One quarter turn of the whole grid; the turns accumulate from face to face (§4 step 2), so
// six of them visit −X, −Y, −Z, +X, +Y, +Z.
void turn_grid(Grid& grid, int face) {
  for (auto& row : grid) {
    for (Vec3& p : row) {
      switch ((face + 2) % 3) {
        case 0: p = {-p.y, p.x, p.z}; break;
        case 1: p = {p.x, -p.z, p.y}; break;
        default: p = {-p.z, p.y, p.x}; break;
      }
    }
  }
}

PatchTriangle sphere_triangle(const Vec3& center, double radius, const Vec3& a, const Vec3& b,
                              const Vec3& c) {
  return {{along(center, radius, a), along(center, radius, b), along(center, radius, c)},
          {a, b, c}};
}

// The cone's first rim direction (§4 cone step 2): perpendicular to the axis, found by crossing
// with +z, or with +x when the axis is (nearly) along z.
Vec3 cone_start_direction(const Vec3& unit_axis) {
  Vec3 c = cross(unit_axis, {0.0, 0.0, 1.0});
  if (length(c) < 1e-6) c = cross(unit_axis, {1.0, 0.0, 0.0});
  return normalize(c);
}

// A point of the canonical torus (§4): tube angle theta, major-circle angle phi.
Vec3 torus_point(double major, double minor, double theta, double phi) {
  const double ring = major + minor * std::sin(theta);
  return {ring * std::cos(phi), ring * std::sin(phi), minor * std::cos(theta)};
}

// normalize(∂E/∂θ × ∂E/∂φ): points away from the tube's centre line.
Vec3 torus_normal(double major, double minor, double theta, double phi) {
  const double ring = major + minor * std::sin(theta);
  const Vec3 d_theta{minor * std::cos(theta) * std::cos(phi),
                     minor * std::cos(theta) * std::sin(phi), -minor * std::sin(theta)};
  const Vec3 d_phi{-ring * std::sin(phi), ring * std::cos(phi), 0.0};
  return normalize(cross(d_theta, d_phi));
}

// steps + 1 angles 0, Δ, Δ+Δ, … accumulated by repeated addition, as the SPD steps the cone,
// torus and disc (§4). (Computing i·Δ instead changes near-zero noise such as 1.22465e-16 and
// with it sample's bytes.)
std::vector<double> accumulated_angles(int steps) {
  const double delta = 2.0 * kPi / steps;
  std::vector<double> angles(steps + 1);
  double angle = 0.0;
  for (double& a : angles) {
    a = angle;
    angle += delta;
  }
  return angles;
}

}  // namespace

std::vector<PatchTriangle> tessellate_sphere(const Vec3& center, double radius, int res) {
  require_resolution(res, "tessellate_sphere");
  Grid grid = sphere_face_grid(res);
  std::vector<PatchTriangle> out;
  out.reserve(static_cast<std::size_t>(12 * res * res));
  for (int face = 0; face < 6; ++face) {
    turn_grid(grid, face);
    for (int u = 0; u < res; ++u) {
      for (int v = 0; v < res; ++v) {
        out.push_back(
            sphere_triangle(center, radius, grid[u][v], grid[u][v + 1], grid[u + 1][v + 1]));
        out.push_back(
            sphere_triangle(center, radius, grid[u + 1][v + 1], grid[u + 1][v], grid[u][v]));
      }
    }
  }
  return out;
}

std::vector<PatchTriangle> tessellate_cone(const Vec3& base, double base_radius, const Vec3& apex,
                                           double apex_radius, int res) {
  require_resolution(res, "tessellate_cone");
  const Vec3 axis = apex - base;
  const Vec3 k = normalize(axis);
  const double height = length(axis);
  const Vec3 e = cone_start_direction(k);
  // A cylinder's surface normal is the rim direction; a cone's leans along the axis by the
  // radius difference over the height (§4 cone step 3).
  const Vec3 start_normal =
      base_radius == apex_radius ? e : normalize(e * height + k * (base_radius - apex_radius));
  const Vec3 apex_offset = e * apex_radius;
  const Vec3 base_offset = e * base_radius;

  const int steps = 4 * res;
  const std::vector<double> angles = accumulated_angles(steps);
  std::vector<Vec3> a(steps + 1), b(steps + 1), n(steps + 1);
  for (int i = 0; i <= steps; ++i) {
    // The rim points rotate about the axis; a rotation's inverse transpose is itself, so the
    // normal turns with the same matrix (the SPD inverts it numerically: ~1e-7 apart, §4).
    const Matrix4 rot = Matrix4::rotate_axis(k, angles[i]);
    a[i] = apex + transform_vector(apex_offset, rot);
    b[i] = base + transform_vector(base_offset, rot);
    n[i] = transform_vector(start_normal, rot);
  }
  std::vector<PatchTriangle> out;
  out.reserve(static_cast<std::size_t>(2 * steps));
  for (int i = 1; i <= steps; ++i) {
    out.push_back({{a[i], a[i - 1], b[i - 1]}, {n[i], n[i - 1], n[i - 1]}});
    out.push_back({{b[i], a[i], b[i - 1]}, {n[i], n[i], n[i - 1]}});
  }
  return out;
}

Matrix4 canonical_frame(const Vec3& center, const Vec3& unit_normal) {
  const Vec3 n = unit_normal;
  const Matrix4 rotation =
      std::abs(n.z) == 1.0 ? Matrix4::rotate_axis({1.0, 0.0, 0.0}, std::acos(n.z))
                           : Matrix4::rotate_axis(normalize(Vec3{-n.y, n.x, 0.0}), std::acos(n.z));
  return rotation * Matrix4::translate(center);
}

std::vector<PatchTriangle> tessellate_torus(const Vec3& center, const Vec3& unit_normal,
                                            double major_radius, double minor_radius, int res_u,
                                            int res_v) {
  require_resolution(res_u, "tessellate_torus");
  require_resolution(res_v, "tessellate_torus");
  const Matrix4 frame = canonical_frame(center, unit_normal);
  const int steps_u = 4 * res_u;  // around the major circle (φ)
  const int steps_v = 4 * res_v;  // around the tube (θ)
  const std::vector<double> phis = accumulated_angles(steps_u);
  const std::vector<double> thetas = accumulated_angles(steps_v);

  Grid points(steps_u + 1, std::vector<Vec3>(steps_v + 1));
  Grid normals = points;
  for (int i = 0; i <= steps_u; ++i) {
    const double phi = phis[i];
    for (int j = 0; j <= steps_v; ++j) {
      const double theta = thetas[j];
      points[i][j] = transform_point(torus_point(major_radius, minor_radius, theta, phi), frame);
      normals[i][j] = transform_vector(torus_normal(major_radius, minor_radius, theta, phi), frame);
    }
  }
  std::vector<PatchTriangle> out;
  out.reserve(static_cast<std::size_t>(2 * steps_u * steps_v));
  for (int i = 0; i < steps_u; ++i) {
    for (int j = 0; j < steps_v; ++j) {
      // (θ+dθ, φ+dφ), (θ, φ+dφ), (θ, φ) and (θ+dθ, φ), (θ+dθ, φ+dφ), (θ, φ): counter-clockwise
      // seen from outside (§4 torus).
      out.push_back({{points[i + 1][j + 1], points[i + 1][j], points[i][j]},
                     {normals[i + 1][j + 1], normals[i + 1][j], normals[i][j]}});
      out.push_back({{points[i][j + 1], points[i + 1][j + 1], points[i][j]},
                     {normals[i][j + 1], normals[i + 1][j + 1], normals[i][j]}});
    }
  }
  return out;
}

std::vector<Quad> tessellate_disc(const Vec3& center, const Vec3& unit_normal, double inner_radius,
                                  double outer_radius, int res) {
  require_resolution(res, "tessellate_disc");
  const Matrix4 frame = canonical_frame(center, unit_normal);
  const int steps = 4 * res;
  const std::vector<double> angles = accumulated_angles(steps);
  auto rim = [&](double radius, double angle) {
    return transform_point({radius * std::cos(angle), radius * std::sin(angle), 0.0}, frame);
  };
  std::vector<Quad> out;
  out.reserve(static_cast<std::size_t>(steps));
  for (int i = 0; i < steps; ++i) {
    out.push_back({rim(outer_radius, angles[i]), rim(outer_radius, angles[i + 1]),
                   rim(inner_radius, angles[i + 1]), rim(inner_radius, angles[i])});
  }
  return out;
}

}  // namespace raygate::scenes

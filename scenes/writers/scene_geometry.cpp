// Camera basis, light intensity and the triangle meshes of the scene writers (scene_geometry.h).
#include "writers/scene_geometry.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "geom/triangulate.h"

namespace raygate::writers {
namespace {

void require(bool condition, const std::string& what) {
  if (!condition) throw std::invalid_argument("unusable view: " + what);
}

Vec3 ring_point(const Vec3& center, const Frame& frame, double radius, double angle) {
  return center + (frame.u * std::cos(angle) + frame.v * std::sin(angle)) * radius;
}

bool has_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double twice_area = length(cross(b - a, c - a));
  return std::isfinite(twice_area) && twice_area > 0.0;
}

// Splits the mesh's polygon (its positions) and keeps only the triangles with area: ear
// clipping cuts collinear vertices as zero-area ears. A triangle stays as written.
void add_triangles(Mesh& mesh) {
  const std::vector<std::array<int, 3>> triangles = mesh.positions.size() == 3
                                                        ? std::vector<std::array<int, 3>>{{0, 1, 2}}
                                                        : triangulate_polygon(mesh.positions);
  for (const std::array<int, 3>& t : triangles) {
    if (has_area(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]])) {
      mesh.triangles.push_back(t);
    }
  }
}

}  // namespace

CameraBasis camera_basis(const nff::View& view) {
  require(view.width > 0 && view.height > 0, "resolution must be positive");
  require(std::isfinite(view.angle_degrees) && view.angle_degrees > 0.0 &&
              view.angle_degrees < 180.0,
          "angle must be between 0 and 180 degrees");
  const Vec3 to_target = view.at - view.from;
  const double distance = length(to_target);
  require(std::isfinite(distance) && distance > 0.0, "'from' and 'at' must differ");
  CameraBasis basis;
  basis.forward = to_target / distance;
  const Vec3 up = view.up - basis.forward * dot(view.up, basis.forward);
  const double up_length = length(up);
  require(std::isfinite(up_length) && up_length > 1e-9 * length(view.up),
          "'up' must not be parallel to the view direction");
  basis.up = up / up_length;
  basis.right = normalize(cross(basis.forward, basis.up));
  basis.half_width = std::tan(view.angle_degrees * std::numbers::pi / 360.0);
  basis.half_height = basis.half_width * view.height / view.width;
  return basis;
}

double light_intensity(std::size_t light_count) {
  return light_count == 0 ? 1.0 : 1.0 / std::sqrt(static_cast<double>(light_count));
}

Frame frame_around(const Vec3& unit_axis) {
  // Cross with the coordinate axis least aligned with w: never close to parallel.
  const double ax = std::fabs(unit_axis.x);
  const double ay = std::fabs(unit_axis.y);
  const double az = std::fabs(unit_axis.z);
  const Vec3 helper =
      ax <= ay && ax <= az ? Vec3{1, 0, 0} : (ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
  const Vec3 u = normalize(cross(helper, unit_axis));
  return {u, cross(unit_axis, u), unit_axis};
}

bool is_degenerate(const nff::Sphere& sphere) {
  return !is_finite(sphere.center) || !std::isfinite(sphere.radius) || sphere.radius == 0.0;
}

bool is_degenerate(const nff::Cone& cone) {
  return !is_finite(cone.base) || !is_finite(cone.apex) || !std::isfinite(cone.base_radius) ||
         !std::isfinite(cone.apex_radius) || length(cone.apex - cone.base) == 0.0 ||
         (cone.base_radius == 0.0 && cone.apex_radius == 0.0);
}

void check_segments(int segments) {
  if (segments < 3 || segments > 1024) {
    throw std::invalid_argument("segments must be between 3 and 1024, not " +
                                std::to_string(segments));
  }
}

Mesh sphere_mesh(const nff::Sphere& sphere, int segments) {
  check_segments(segments);
  const int bands = segments / 2 < 2 ? 2 : segments / 2;
  const double r = std::fabs(sphere.radius);
  const Frame frame{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  Mesh mesh;
  auto add = [&](const Vec3& unit) {
    mesh.positions.push_back(sphere.center + unit * r);
    mesh.normals.push_back(unit);
  };
  add(frame.w);  // north pole: index 0
  for (int band = 1; band < bands; ++band) {
    const double polar = std::numbers::pi * band / bands;
    for (int i = 0; i < segments; ++i) {
      const double around = 2.0 * std::numbers::pi * i / segments;
      add(ring_point({}, frame, std::sin(polar), around) + frame.w * std::cos(polar));
    }
  }
  add(-frame.w);  // south pole: last index
  const int south = static_cast<int>(mesh.positions.size()) - 1;
  auto ring = [segments](int band, int i) { return 1 + (band - 1) * segments + i % segments; };
  for (int i = 0; i < segments; ++i) {
    mesh.triangles.push_back({0, ring(1, i), ring(1, i + 1)});
    for (int band = 1; band + 1 < bands; ++band) {
      mesh.triangles.push_back({ring(band, i), ring(band + 1, i), ring(band + 1, i + 1)});
      mesh.triangles.push_back({ring(band, i), ring(band + 1, i + 1), ring(band, i + 1)});
    }
    mesh.triangles.push_back({south, ring(bands - 1, i + 1), ring(bands - 1, i)});
  }
  return mesh;
}

Mesh cone_mesh(const nff::Cone& cone, int segments) {
  check_segments(segments);
  const Vec3 axis = cone.apex - cone.base;
  const double height = length(axis);
  const Frame frame = frame_around(axis / height);
  const double rb = std::fabs(cone.base_radius);
  const double ra = std::fabs(cone.apex_radius);
  Mesh mesh;
  // Vertex 2i is on the base rim, 2i+1 on the apex rim, both at angle i: a rim of radius 0
  // repeats its point, each copy with the normal of its own line along the side.
  for (int i = 0; i < segments; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / segments;
    const Vec3 radial = ring_point({}, frame, 1.0, angle);
    const Vec3 normal = normalize(radial * height + frame.w * (rb - ra));
    mesh.positions.push_back(ring_point(cone.base, frame, rb, angle));
    mesh.normals.push_back(normal);
    mesh.positions.push_back(ring_point(cone.apex, frame, ra, angle));
    mesh.normals.push_back(normal);
  }
  for (int i = 0; i < segments; ++i) {
    const int b0 = 2 * i;
    const int a0 = b0 + 1;
    const int b1 = 2 * ((i + 1) % segments);
    const int a1 = b1 + 1;
    if (rb > 0.0) mesh.triangles.push_back({b0, b1, a1});
    if (ra > 0.0) mesh.triangles.push_back({b0, a1, a0});
  }
  return mesh;
}

Mesh polygon_mesh(const nff::Polygon& polygon) {
  Mesh mesh;
  mesh.positions = polygon.vertices;
  add_triangles(mesh);
  return mesh;
}

Mesh patch_mesh(const nff::Patch& patch) {
  Mesh mesh;
  mesh.positions = patch.vertices;
  mesh.normals = patch.normals;
  add_triangles(mesh);
  return mesh;
}

}  // namespace raygate::writers

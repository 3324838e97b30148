// The writers' shared geometry: the baseline's camera basis, tessellated spheres and open cones
// (closed or open as they should be, outward winding, exact normals), and polygons split into
// triangles that cover exactly the polygon, concave ones included (the gears' 144-gons).
#include "writers/scene_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "geom/triangulate.h"
#include "spd.h"
#include "writer_test_support.h"

namespace raygate::writers {
namespace {

Vec3 triangle_normal(const Mesh& mesh, const std::array<int, 3>& t) {
  const Vec3& a = mesh.positions[t[0]];
  return cross(mesh.positions[t[1]] - a, mesh.positions[t[2]] - a);
}

// Every edge is used once in each direction: a closed, consistently wound surface.
void expect_closed(const Mesh& mesh) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, uses] : edges) {
    EXPECT_EQ(uses, 1);
    EXPECT_EQ(edges.count({edge.second, edge.first}), 1u) << edge.first << "-" << edge.second;
  }
}

struct Point2 {
  double u;
  double v;
};

Point2 project(const Vec3& p, int drop) {
  return drop == 0 ? Point2{p.y, p.z} : (drop == 1 ? Point2{p.x, p.z} : Point2{p.x, p.y});
}

int dominant_axis(const Vec3& n) {
  const double ax = std::fabs(n.x), ay = std::fabs(n.y), az = std::fabs(n.z);
  return ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
}

// Even-odd rule, independent of the triangulator.
bool inside_polygon(const std::vector<Point2>& ring, Point2 p) {
  bool inside = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Point2 a = ring[i], b = ring[j];
    if ((a.v > p.v) != (b.v > p.v) && p.u < (b.u - a.u) * (p.v - a.v) / (b.v - a.v) + a.u) {
      inside = !inside;
    }
  }
  return inside;
}

bool inside_triangle(Point2 a, Point2 b, Point2 c, Point2 p) {
  const auto side = [](Point2 s, Point2 e, Point2 q) {
    return (e.u - s.u) * (q.v - s.v) - (e.v - s.v) * (q.u - s.u);
  };
  const double d1 = side(a, b, p), d2 = side(b, c, p), d3 = side(c, a, p);
  return (d1 > 0 && d2 > 0 && d3 > 0) || (d1 < 0 && d2 < 0 && d3 < 0);
}

// n-2 triangles wound like the polygon, whose areas add up to the polygon's, and every sample
// point inside the polygon lies in exactly one triangle, every point outside in none.
void expect_exact_cover(const std::vector<Vec3>& polygon, const Mesh& mesh, int grid) {
  const Vec3 area_normal = polygon_area_normal(polygon);
  EXPECT_EQ(mesh.triangles.size(), polygon.size() - 2);
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 n = triangle_normal(mesh, t);
    EXPECT_GT(dot(n, area_normal), 0.0) << "triangle wound against the polygon";
    area += length(n) / 2.0;
  }
  EXPECT_NEAR(area, length(area_normal) / 2.0, 1e-9 * area);

  const int drop = dominant_axis(area_normal);
  std::vector<Point2> ring;
  double lo_u = 1e300, hi_u = -1e300, lo_v = 1e300, hi_v = -1e300;
  for (const Vec3& p : polygon) {
    ring.push_back(project(p, drop));
    lo_u = std::min(lo_u, ring.back().u), hi_u = std::max(hi_u, ring.back().u);
    lo_v = std::min(lo_v, ring.back().v), hi_v = std::max(hi_v, ring.back().v);
  }
  int mismatches = 0;
  for (int i = 0; i < grid; ++i) {
    for (int j = 0; j < grid; ++j) {
      // Irrational offsets keep samples off the edges and vertices.
      const Point2 p{lo_u + (hi_u - lo_u) * (i + 0.5 + 0.1234567) / (grid + 1),
                     lo_v + (hi_v - lo_v) * (j + 0.5 + 0.3141593) / (grid + 1)};
      int covering = 0;
      for (const auto& t : mesh.triangles) {
        covering += inside_triangle(project(mesh.positions[t[0]], drop),
                                    project(mesh.positions[t[1]], drop),
                                    project(mesh.positions[t[2]], drop), p);
      }
      mismatches += covering != (inside_polygon(ring, p) ? 1 : 0);
    }
  }
  EXPECT_EQ(mismatches, 0);
}

TEST(WriterGeometry, CameraBasisIsTheBaselinesRightHandedOne) {
  const nff::Scene scene = test::parse();
  const CameraBasis c = camera_basis(scene.view);
  EXPECT_EQ(c.forward, (Vec3{0, 1, 0}));
  EXPECT_EQ(c.up, (Vec3{0, 0, 1}));
  EXPECT_EQ(c.right, (Vec3{1, 0, 0}));  // forward x up
  EXPECT_NEAR(c.half_width, std::tan(20.0 * std::numbers::pi / 180.0), 1e-15);
  EXPECT_NEAR(c.half_height, c.half_width * 48.0 / 64.0, 1e-15);
}

TEST(WriterGeometry, RejectsViewsTheBaselineRejects) {
  nff::View view = test::parse().view;
  view.up = {0, 2, 0};  // parallel to the view direction
  EXPECT_THROW(camera_basis(view), std::invalid_argument);
  view = test::parse().view;
  view.at = view.from;
  EXPECT_THROW(camera_basis(view), std::invalid_argument);
  view = test::parse().view;
  view.angle_degrees = 180.0;
  EXPECT_THROW(camera_basis(view), std::invalid_argument);
}

TEST(WriterGeometry, LightIntensityIsOneOverRootN) {
  EXPECT_DOUBLE_EQ(light_intensity(1), 1.0);
  EXPECT_DOUBLE_EQ(light_intensity(4), 0.5);
  EXPECT_DOUBLE_EQ(light_intensity(7), 1.0 / std::sqrt(7.0));
}

TEST(WriterGeometry, FramesAreRightHandedAndOrthonormal) {
  for (const Vec3& axis :
       {Vec3{0, 0, 1}, Vec3{1, 0, 0}, Vec3{0, -1, 0}, normalize(Vec3{1, 2, -3})}) {
    const Frame f = frame_around(axis);
    EXPECT_NEAR(length(f.u), 1.0, 1e-15);
    EXPECT_NEAR(length(f.v), 1.0, 1e-15);
    EXPECT_NEAR(dot(f.u, f.w), 0.0, 1e-15);
    EXPECT_NEAR(length(cross(f.u, f.v) - f.w), 0.0, 1e-15);
  }
}

TEST(WriterGeometry, SphereMeshIsClosedOutwardAndOnTheSphere) {
  const nff::Sphere sphere{{1, 2, 3}, 0.5, 0, {}};
  const Mesh mesh = sphere_mesh(sphere, 16);
  EXPECT_EQ(mesh.positions.size(), 2u + 16u * 7u);  // poles + 7 rings of 16
  EXPECT_EQ(mesh.triangles.size(), 2u * 16u * 7u);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    EXPECT_NEAR(length(mesh.positions[i] - sphere.center), 0.5, 1e-15);
    EXPECT_NEAR(length(mesh.normals[i] - (mesh.positions[i] - sphere.center) / 0.5), 0.0, 1e-15);
  }
  for (const auto& t : mesh.triangles) {
    const Vec3 centroid =
        (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
    EXPECT_GT(dot(triangle_normal(mesh, t), centroid - sphere.center), 0.0);
  }
  expect_closed(mesh);
}

TEST(WriterGeometry, ConeMeshIsAnOpenSideWoundOutward) {
  const nff::Cone cone{{0, 0, 0}, 1.0, {0, 0, 2}, 0.25, 0, {}};
  const Mesh mesh = cone_mesh(cone, 12);
  EXPECT_EQ(mesh.positions.size(), 24u);
  EXPECT_EQ(mesh.triangles.size(), 24u);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3& p = mesh.positions[i];
    const double expected_radius = i % 2 == 0 ? 1.0 : 0.25;  // base rim, apex rim
    EXPECT_NEAR(std::hypot(p.x, p.y), expected_radius, 1e-15);
    EXPECT_NEAR(p.z, i % 2 == 0 ? 0.0 : 2.0, 1e-15);
    // The normal is perpendicular to the side line through this point and points outward.
    const Vec3 side = mesh.positions[i | 1] - mesh.positions[i & ~std::size_t{1}];
    EXPECT_NEAR(dot(mesh.normals[i], side), 0.0, 1e-15);
    EXPECT_GT(mesh.normals[i].x * p.x + mesh.normals[i].y * p.y, 0.0);
  }
  for (const auto& t : mesh.triangles) {
    // Open: no triangle lies in a rim's plane (a cap would).
    EXPECT_FALSE(t[0] % 2 == t[1] % 2 && t[1] % 2 == t[2] % 2);
    const Vec3 centroid =
        (mesh.positions[t[0]] + mesh.positions[t[1]] + mesh.positions[t[2]]) / 3.0;
    EXPECT_GT(dot(triangle_normal(mesh, t), Vec3{centroid.x, centroid.y, 0}), 0.0);
  }
}

TEST(WriterGeometry, PointedConeHasOneTrianglePerSegment) {
  const nff::Cone cone{{0, 0, 0}, 1.0, {0, 0, 1}, 0.0, 0, {}};
  const Mesh mesh = cone_mesh(cone, 8);
  EXPECT_EQ(mesh.triangles.size(), 8u);
  for (const auto& t : mesh.triangles) EXPECT_GT(length(triangle_normal(mesh, t)), 0.0);
}

TEST(WriterGeometry, ConcavePolygonIsCoveredExactly) {
  const nff::Scene scene = test::parse();
  ASSERT_EQ(scene.polygons.size(), 1u);
  const Mesh mesh = polygon_mesh(scene.polygons[0]);
  expect_exact_cover(scene.polygons[0].vertices, mesh, 60);
}

TEST(WriterGeometry, GearFacesOf144VerticesAreCoveredExactly) {
  std::ostringstream text;
  scenes::generate("gears", {.size = 1}, text);
  const nff::Scene scene = nff::parse_nff(text.str(), "gears.nff");
  int faces = 0;
  for (const nff::Polygon& polygon : scene.polygons) {
    if (polygon.vertices.size() < 100) continue;
    ASSERT_EQ(polygon.vertices.size(), 144u);
    expect_exact_cover(polygon.vertices, polygon_mesh(polygon), 40);
    ++faces;
  }
  EXPECT_GT(faces, 0);
}

TEST(WriterGeometry, PatchKeepsItsNormals) {
  const nff::Scene scene = test::parse();
  ASSERT_EQ(scene.patches.size(), 1u);
  const Mesh mesh = patch_mesh(scene.patches[0]);
  EXPECT_EQ(mesh.normals, scene.patches[0].normals);
  ASSERT_EQ(mesh.triangles.size(), 1u);
  EXPECT_EQ(mesh.triangles[0], (std::array<int, 3>{0, 1, 2}));
}

TEST(WriterGeometry, ZeroAreaPatchGivesNoTriangles) {
  const nff::Patch patch{
      {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}}, {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}}, 0, {}};
  EXPECT_TRUE(patch_mesh(patch).triangles.empty());
}

}  // namespace
}  // namespace raygate::writers

// The polygon triangulator: n-2 triangles that keep the polygon's winding, cover exactly its
// area and contain no other vertex, on simple shapes, the gears' concave 144-gons (spd-spec.md
// §3.2), polygons in every plane and winding, degenerate input, and random polygons.
#include "geom/triangulate.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <random>
#include <utility>
#include <vector>

namespace raygate {
namespace {

constexpr double kPi = 3.14159265358979323846;
using Triangles = std::vector<std::array<int, 3>>;

// Twice the signed area of the polygon projected onto axes (a, b): the shoelace formula.
double shoelace(const std::vector<Vec3>& p, int a, int b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    // Relative to the first vertex, or polygons far from the origin lose their area.
    const Vec3 s = p[i] - p[0];
    const Vec3 t = p[(i + 1) % p.size()] - p[0];
    sum += s[a] * t[b] - t[a] * s[b];
  }
  return sum;
}

// The test's own choice of plane, independent of the implementation: of (y,z), (z,x), (x,y),
// the one with the largest projected area. The sign of that area is the polygon's winding.
struct Plane {
  int a = 0;
  int b = 1;
};

Plane best_plane(const std::vector<Vec3>& p) {
  const Plane planes[3] = {{1, 2}, {2, 0}, {0, 1}};
  Plane best = planes[0];
  for (const Plane& plane : planes) {
    if (std::fabs(shoelace(p, plane.a, plane.b)) > std::fabs(shoelace(p, best.a, best.b))) {
      best = plane;
    }
  }
  return best;
}

double tri_area2(const Vec3& p, const Vec3& q, const Vec3& r, const Plane& pl) {
  return (q[pl.a] - p[pl.a]) * (r[pl.b] - p[pl.b]) - (q[pl.b] - p[pl.b]) * (r[pl.a] - p[pl.a]);
}

// Checks everything a triangulation of a simple polygon must satisfy.
void expect_valid(const std::vector<Vec3>& p, const Triangles& triangles) {
  const int n = static_cast<int>(p.size());
  ASSERT_EQ(triangles.size(), p.size() - 2);
  const Plane plane = best_plane(p);
  const double area = shoelace(p, plane.a, plane.b);
  const double sign = area > 0 ? 1.0 : -1.0;
  double scale = 0.0;
  for (const Vec3& v : p) {
    scale = std::max(
        {scale, std::fabs(v[plane.a] - p[0][plane.a]), std::fabs(v[plane.b] - p[0][plane.b])});
  }
  const double tolerance = 1e-12 * scale * scale;
  double sum = 0.0;
  for (const auto& t : triangles) {
    for (const int i : t) ASSERT_TRUE(i >= 0 && i < n) << i;
    ASSERT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    const double a = tri_area2(p[t[0]], p[t[1]], p[t[2]], plane);
    EXPECT_GE(sign * a, -tolerance)
        << "triangle " << t[0] << " " << t[1] << " " << t[2] << " is inverted";
    sum += a;
    for (int k = 0; k < n; ++k) {
      const Vec3& q = p[k];
      if (q == p[t[0]] || q == p[t[1]] || q == p[t[2]]) continue;
      const bool inside = sign * tri_area2(p[t[0]], p[t[1]], q, plane) > tolerance &&
                          sign * tri_area2(p[t[1]], p[t[2]], q, plane) > tolerance &&
                          sign * tri_area2(p[t[2]], p[t[0]], q, plane) > tolerance;
      EXPECT_FALSE(inside) << "vertex " << k << " inside triangle " << t[0] << " " << t[1] << " "
                           << t[2];
    }
  }
  EXPECT_NEAR(sum, area, 1e-9 * std::fabs(area));
}

std::vector<Vec3> flat(std::initializer_list<std::pair<double, double>> points) {
  std::vector<Vec3> out;
  for (const auto& [x, y] : points) out.push_back({x, y, 0.0});
  return out;
}

std::vector<Vec3> reversed(std::vector<Vec3> p) {
  std::reverse(p.begin(), p.end());
  return p;
}

// Rodrigues' rotation about a unit axis.
Vec3 rotate(const Vec3& v, const Vec3& k, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return v * c + cross(k, v) * s + k * (dot(k, v) * (1 - c));
}

std::vector<Vec3> rotated(const std::vector<Vec3>& p, const Vec3& axis, double angle) {
  std::vector<Vec3> out;
  for (const Vec3& v : p) out.push_back(rotate(v, normalize(axis), angle));
  return out;
}

// A gear face as spd-spec.md §3.2 builds it: 36 teeth of 4 points, outer radius 0.995R, inner
// 0.9R; the top runs counter-clockwise seen from +z, the bottom clockwise.
std::vector<Vec3> gear_face(const Vec3& centre, double r, double phi0, bool top) {
  const double a = 2 * kPi / 36;
  const double ro = 0.995 * r;
  const double ri = 0.9 * r;
  const double s = top ? 1.0 : -1.0;
  std::vector<Vec3> out;
  for (int k = 0; k < 36; ++k) {
    const double g = phi0 + s * 2 * kPi * k / 36;
    const double radii[4] = {ro, ro, ri, ri};
    const double angles[4] = {g - s * 0.19 * a, g + s * 0.19 * a, g + s * 0.3 * a, g + s * 0.7 * a};
    for (int i = 0; i < 4; ++i) {
      out.push_back(centre +
                    Vec3{radii[i] * std::cos(angles[i]), radii[i] * std::sin(angles[i]), 0.0});
    }
  }
  return out;
}

TEST(Triangulate, Square) {
  const auto square = flat({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  expect_valid(square, triangulate_polygon(square));
  expect_valid(reversed(square), triangulate_polygon(reversed(square)));
}

TEST(Triangulate, TriangleIsItself) {
  const auto triangle = flat({{0, 0}, {1, 0}, {0, 1}});
  EXPECT_EQ(triangulate_polygon(triangle), (Triangles{{2, 0, 1}}));
}

TEST(Triangulate, ConcaveL) {
  const auto l = flat({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  expect_valid(l, triangulate_polygon(l));
  expect_valid(reversed(l), triangulate_polygon(reversed(l)));
}

TEST(Triangulate, FivePointedStar) {
  std::vector<Vec3> star;
  for (int i = 0; i < 10; ++i) {
    const double r = i % 2 == 0 ? 1.0 : 0.38;
    star.push_back({r * std::cos(kPi / 2 + i * kPi / 5), r * std::sin(kPi / 2 + i * kPi / 5), 0});
  }
  expect_valid(star, triangulate_polygon(star));
  expect_valid(reversed(star), triangulate_polygon(reversed(star)));
}

TEST(Triangulate, Comb) {
  // Deep notches, and a base edge full of collinear vertices.
  std::vector<Vec3> comb;
  for (int i = 0; i <= 10; ++i) comb.push_back({double(i), 0, 0});
  for (int i = 10; i >= 1; --i) {
    comb.push_back({double(i), 5, 0});
    comb.push_back({i - 0.5, 1, 0});
  }
  comb.push_back({0, 5, 0});
  expect_valid(comb, triangulate_polygon(comb));
  expect_valid(reversed(comb), triangulate_polygon(reversed(comb)));
}

TEST(Triangulate, GearFaces) {
  const int n = 4;
  const double r = 1.0 / (n - (n - 1) * 0.05);
  for (const double phi0 : {0.0, kPi / 36}) {
    const Vec3 centre{-1 + r + 1.9 * r, -1 + r, 1 - 2.0 / n};
    const auto top = gear_face(centre, r, phi0, true);
    const auto bottom = gear_face(centre - Vec3{0, 0, 0.1}, r, phi0, false);
    ASSERT_EQ(top.size(), 144u);
    EXPECT_GT(shoelace(top, 0, 1), 0.0);
    EXPECT_LT(shoelace(bottom, 0, 1), 0.0);
    expect_valid(top, triangulate_polygon(top));
    expect_valid(bottom, triangulate_polygon(bottom));
  }
}

TEST(Triangulate, GearInEveryOrientation) {
  const auto gear = gear_face({0.2, -0.3, 0.5}, 0.5, 0.0, true);
  const Vec3 axes[] = {{1, 0, 0}, {0, 1, 0}, {1, 2, 3}, {-3, 1, 0.5}};
  for (const Vec3& axis : axes) {
    for (const double angle : {0.5, kPi / 2, 2.0, kPi, -kPi / 2}) {
      const auto p = rotated(gear, axis, angle);
      const Triangles triangles = triangulate_polygon(p);
      expect_valid(p, triangles);
      // In 3D too: every triangle faces where the polygon faces.
      const Vec3 facing = rotate({0, 0, 1}, normalize(axis), angle);
      for (const auto& t : triangles) {
        EXPECT_GT(dot(cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]), facing), 0.0);
      }
      if (HasFailure()) return;
    }
  }
}

TEST(Triangulate, FarFromOrigin) {
  const auto gear = gear_face({1e6, -2e6, 3e5}, 0.1, kPi / 36, true);
  expect_valid(gear, triangulate_polygon(gear));
}

TEST(Triangulate, AxisPlanesBothWindings) {
  // xz and yz planes exercise the projection's handedness for each dropped axis.
  const auto l = flat({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}});
  std::vector<Vec3> xz;
  std::vector<Vec3> yz;
  for (const Vec3& v : l) {
    xz.push_back({v.x, 3.0, v.y});
    yz.push_back({-1.0, v.x, v.y});
  }
  for (const auto& p : {xz, reversed(xz), yz, reversed(yz)}) {
    expect_valid(p, triangulate_polygon(p));
  }
}

TEST(Triangulate, CollinearVerticesOnEdges) {
  const auto square =
      flat({{0, 0}, {0.5, 0}, {1, 0}, {1, 0.5}, {1, 1}, {0.5, 1}, {0, 1}, {0, 0.5}});
  expect_valid(square, triangulate_polygon(square));
  expect_valid(reversed(square), triangulate_polygon(reversed(square)));
}

TEST(Triangulate, RepeatedVertices) {
  const auto doubled = flat({{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}});
  expect_valid(doubled, triangulate_polygon(doubled));
  const auto closed = flat({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}});
  expect_valid(closed, triangulate_polygon(closed));
  const auto tripled =
      flat({{0, 0}, {0, 0}, {0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 1}, {1, 2}, {0, 2}});
  expect_valid(tripled, triangulate_polygon(tripled));
}

TEST(Triangulate, HoleJoinedByABridge) {
  // A square with a square hole, joined by a doubled edge: the ring touches itself.
  const auto keyhole =
      flat({{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}});
  expect_valid(keyhole, triangulate_polygon(keyhole));
}

TEST(Triangulate, DegenerateInputGivesNothing) {
  EXPECT_TRUE(triangulate_polygon({}).empty());
  EXPECT_TRUE(triangulate_polygon(flat({{0, 0}, {1, 1}})).empty());
  EXPECT_TRUE(triangulate_polygon(flat({{0, 0}, {1, 1}, {2, 2}, {3, 3}})).empty());
  EXPECT_TRUE(triangulate_polygon(flat({{1, 1}, {1, 1}, {1, 1}})).empty());
  EXPECT_TRUE(triangulate_polygon({{0, 0, 0}, {NAN, 0, 0}, {0, 1, 0}}).empty());
}

// Not simple: no guarantee of coverage, but indices stay in range and it terminates.
void expect_safe(const std::vector<Vec3>& p, const Triangles& triangles) {
  EXPECT_LE(triangles.size(), p.size() >= 2 ? p.size() - 2 : 0);
  for (const auto& t : triangles) {
    for (const int i : t) ASSERT_TRUE(i >= 0 && i < static_cast<int>(p.size()));
    ASSERT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
  }
}

TEST(Triangulate, SelfIntersectingIsSafe) {
  const auto bowtie = flat({{0, 0}, {2, 2}, {2, 0}, {0, 2}});
  expect_safe(bowtie, triangulate_polygon(bowtie));
  const auto lopsided = flat({{0, 0}, {3, 3}, {3, 0}, {0, 1}});
  expect_safe(lopsided, triangulate_polygon(lopsided));
}

// Star-shaped polygons around the origin with random radii are simple however jagged they are.
TEST(Triangulate, RandomStarShapedPolygons) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int round = 0; round < 300; ++round) {
    const int n = 3 + static_cast<int>(unit(random) * 80);
    std::vector<double> angles;
    for (int i = 0; i < n; ++i) angles.push_back(unit(random) * 2 * kPi);
    std::sort(angles.begin(), angles.end());
    if (std::adjacent_find(angles.begin(), angles.end()) != angles.end()) continue;
    std::vector<Vec3> p;
    for (const double angle : angles) {
      const double r = 0.05 + unit(random);
      p.push_back({r * std::cos(angle), r * std::sin(angle), 0});
    }
    // Star-shaped only if the origin is inside: every angular gap below pi.
    bool origin_inside = angles.front() + 2 * kPi - angles.back() < kPi;
    for (int i = 1; i < n; ++i) origin_inside = origin_inside && angles[i] - angles[i - 1] < kPi;
    if (!origin_inside) continue;
    if (round % 2 == 1) p = reversed(p);
    p = rotated(p, {unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5}, unit(random) * 6);
    expect_valid(p, triangulate_polygon(p));
    if (HasFailure()) {
      ADD_FAILURE() << "round " << round;
      return;
    }
  }
}

TEST(Triangulate, RandomPointCloudsAreSafe) {
  std::mt19937 random(11);
  std::uniform_int_distribution<int> coordinate(-3, 3);  // small grid: many repeats and collinear
  for (int round = 0; round < 2000; ++round) {
    std::vector<Vec3> p(3 + round % 20);
    for (Vec3& v : p) {
      v = {double(coordinate(random)), double(coordinate(random)), 0.5 * coordinate(random)};
    }
    expect_safe(p, triangulate_polygon(p));
    if (HasFailure()) return;
  }
}

TEST(Triangulate, LargePolygonFinishes) {
  std::vector<Vec3> p;
  for (int i = 0; i < 2000; ++i) {
    const double angle = 2 * kPi * i / 2000;
    const double r = i % 2 == 0 ? 1.0 : 0.6;
    p.push_back({r * std::cos(angle), r * std::sin(angle), 0});
  }
  EXPECT_EQ(triangulate_polygon(p).size(), 1998u);
}

TEST(PolygonAreaNormal, LengthIsTwiceTheArea) {
  const auto square = flat({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  const Vec3 normal = polygon_area_normal(square);
  EXPECT_EQ(normal, (Vec3{0, 0, 8}));
  EXPECT_EQ(polygon_area_normal(reversed(square)), (Vec3{0, 0, -8}));
  EXPECT_EQ(polygon_area_normal(flat({{0, 0}, {1, 1}})), Vec3{});
}

}  // namespace
}  // namespace raygate

// Tessellation (spd-spec.md §4): triangle counts per primitive, vertices on the surface, unit
// outward normals, counter-clockwise winding seen from outside, and the tessellated-mode totals
// of §4's table for the extra scenes at their default sizes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>
#include <sstream>
#include <streambuf>
#include <string>
#include <vector>

#include "generators/generators.h"
#include "lib/nff_writer.h"
#include "lib/tessellate.h"

namespace raygate::test {
namespace {

using scenes::PatchTriangle;

constexpr double kTight = 1e-12;

Vec3 face_normal(const std::array<Vec3, 3>& v) { return cross(v[1] - v[0], v[2] - v[0]); }
Vec3 centroid(const std::array<Vec3, 3>& v) { return (v[0] + v[1] + v[2]) / 3.0; }
double area(const std::array<Vec3, 3>& v) { return 0.5 * length(face_normal(v)); }

// How gtest prints a case (instead of its bytes).
template <class Case>
requires requires(const Case& c) { c.name; }
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

// Test names from the cases' `name` field.
struct CaseName {
  template <class Case>
  std::string operator()(const ::testing::TestParamInfo<Case>& c) const {
    return c.param.name;
  }
};

void expect_unit_normals(const PatchTriangle& t) {
  for (const Vec3& n : t.normals) EXPECT_NEAR(length(n), 1.0, kTight);
}

// ---- sphere ------------------------------------------------------------------------------

class SphereTessellation : public ::testing::TestWithParam<int> {};

TEST_P(SphereTessellation, CountSurfaceNormalsAndWinding) {
  const int res = GetParam();
  const Vec3 c{1.0, -2.0, 0.5};
  const double r = 0.75;
  const auto tris = scenes::tessellate_sphere(c, r, res);
  ASSERT_EQ(tris.size(), static_cast<std::size_t>(12 * res * res));
  double total_area = 0.0;
  for (const PatchTriangle& t : tris) {
    expect_unit_normals(t);
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(length(t.vertices[k] - c), r, kTight);                       // on the sphere
      EXPECT_NEAR(length(t.normals[k] - (t.vertices[k] - c) / r), 0.0, 1e-9);  // radial
    }
    EXPECT_GT(dot(face_normal(t.vertices), centroid(t.vertices) - c), 0.0);  // outward
    total_area += area(t.vertices);
  }
  // An inscribed polyhedron covering all six cube faces: a little under 4πr².
  const double sphere_area = 4.0 * std::numbers::pi * r * r;
  EXPECT_LT(total_area, sphere_area);
  EXPECT_GT(total_area, (res == 1 ? 0.6 : 0.85) * sphere_area);
}

INSTANTIATE_TEST_SUITE_P(Resolutions, SphereTessellation, ::testing::Values(1, 2, 3, 4, 5));

// ---- cylinder and cone -------------------------------------------------------------------

struct ConeCase {
  const char* name;
  Vec3 base;
  double base_radius;
  Vec3 apex;
  double apex_radius;
  int res;
};

class ConeTessellation : public ::testing::TestWithParam<ConeCase> {};

TEST_P(ConeTessellation, CountSurfaceNormalsAndWinding) {
  const ConeCase& p = GetParam();
  const auto tris = scenes::tessellate_cone(p.base, p.base_radius, p.apex, p.apex_radius, p.res);
  ASSERT_EQ(tris.size(), static_cast<std::size_t>(8 * p.res));
  const Vec3 k = normalize(p.apex - p.base);
  const double h = length(p.apex - p.base);
  auto radial = [&](const Vec3& v) {
    const Vec3 q = v - p.base;
    return q - k * dot(q, k);
  };
  for (const PatchTriangle& t : tris) {
    expect_unit_normals(t);
    for (int i = 0; i < 3; ++i) {
      const double along = dot(t.vertices[i] - p.base, k) / h;
      EXPECT_TRUE(std::abs(along) < kTight || std::abs(along - 1.0) < kTight) << along;
      const double expected_r = along < 0.5 ? p.base_radius : p.apex_radius;
      EXPECT_NEAR(length(radial(t.vertices[i])), expected_r, kTight);  // on the rim
      // The surface normal: radial·h + axis·(r_base − r_apex), normalised (§4 step 3).
      const Vec3 out = normalize(radial(t.vertices[i]));
      if (expected_r > 0.0) {
        const Vec3 want = normalize(out * h + k * (p.base_radius - p.apex_radius));
        EXPECT_NEAR(length(t.normals[i] - want), 0.0, 1e-9);
      }
    }
    if (area(t.vertices) > 1e-12) {
      EXPECT_GT(dot(face_normal(t.vertices), radial(centroid(t.vertices))), 0.0);  // outward
    }
  }
  // The strip closes: the last step ends where the first began.
  EXPECT_NEAR(length(tris.back().vertices[1] - tris.front().vertices[1]), 0.0, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, ConeTessellation,
    ::testing::Values(
        ConeCase{"cylinder_along_x", {0, 0, 0}, 0.5, {2, 0, 0}, 0.5, 3},
        // Along z, k × z vanishes and the start direction comes from k × x (§4 step 2).
        ConeCase{"cylinder_along_z", {1, 1, -1}, 0.25, {1, 1, 2}, 0.25, 2},
        ConeCase{"cylinder_oblique", {0.1, 0.2, 0.3}, 0.1, {1, -2, 3}, 0.1, 4},
        ConeCase{"cone_tree_like", {0, 0, 0}, 0.2, {0, 0.3, 1.4}, 0.12, 3},
        ConeCase{"cone_to_point", {0, -2, 0}, 2.0, {0, 2, 0}, 0.0, 1}),
    CaseName());

// ---- torus and disc (NFF has neither; `sample` always tessellates them) -------------------

struct TorusCase {
  const char* name;
  Vec3 center;
  Vec3 normal;
  int res_u;
  int res_v;
};

class TorusTessellation : public ::testing::TestWithParam<TorusCase> {};

TEST_P(TorusTessellation, CountSurfaceNormalsAndWinding) {
  const TorusCase& p = GetParam();
  const double major = 2.0, minor = 0.5;
  const Vec3 n = normalize(p.normal);
  const auto tris = scenes::tessellate_torus(p.center, n, major, minor, p.res_u, p.res_v);
  ASSERT_EQ(tris.size(), static_cast<std::size_t>(32 * p.res_u * p.res_v));
  // The nearest point of the tube's centre circle.
  auto spine = [&](const Vec3& v) {
    const Vec3 q = v - p.center;
    return p.center + normalize(q - n * dot(q, n)) * major;
  };
  for (const PatchTriangle& t : tris) {
    expect_unit_normals(t);
    for (int i = 0; i < 3; ++i) {
      const Vec3 from_spine = t.vertices[i] - spine(t.vertices[i]);
      EXPECT_NEAR(length(from_spine), minor, 1e-12);
      EXPECT_NEAR(length(t.normals[i] - from_spine / minor), 0.0, 1e-9);
    }
    // Counter-clockwise about the outward vertex normals (robust even at 4 steps a turn).
    EXPECT_GT(dot(face_normal(t.vertices), t.normals[0] + t.normals[1] + t.normals[2]), 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Frames, TorusTessellation,
    ::testing::Values(TorusCase{"sample_cyan", {-1, 0, 0}, {1, 1, -0.5}, 3, 3},
                      TorusCase{"sample_yellow", {0, 0, 0}, {0, 1, -0.5}, 3, 3},
                      TorusCase{"along_z", {0, 0, 1}, {0, 0, 1}, 2, 1},
                      TorusCase{"along_minus_z", {0, 0, 1}, {0, 0, -1}, 1, 2}),
    CaseName());

TEST(CanonicalFrame, TakesZToTheNormalAndOriginToTheCentre) {
  for (const Vec3& raw : {Vec3{1, 1, -0.5}, Vec3{0, 1, 0}, Vec3{0, 0, 1}, Vec3{0, 0, -1}}) {
    const Vec3 n = normalize(raw);
    const Vec3 c{1, 2, 3};
    const scenes::Matrix4 m = scenes::canonical_frame(c, n);
    EXPECT_NEAR(length(scenes::transform_vector({0, 0, 1}, m) - n), 0.0, kTight);
    EXPECT_NEAR(length(scenes::transform_point({0, 0, 0}, m) - c), 0.0, kTight);
  }
}

TEST(DiscTessellation, QuadsLieInThePlaneAndFaceTheNormal) {
  const Vec3 c{0, -2, 0}, n{0, 1, 0};
  const auto quads = scenes::tessellate_disc(c, n, 1.0, 4.0, 4);
  ASSERT_EQ(quads.size(), 16U);
  for (const scenes::Quad& q : quads) {
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(dot(q[i] - c, n), 0.0, kTight);
      EXPECT_NEAR(length(q[i] - c), i < 2 ? 4.0 : 1.0, kTight);  // outer, outer, inner, inner
    }
    EXPECT_GT(dot(face_normal({q[0], q[1], q[2]}), n), 0.0);
  }
}

TEST(DiscTessellation, CentredDiscCollapsesToTrianglesInTheWriter) {
  std::ostringstream text;
  scenes::NffWriter writer(text);
  for (const scenes::Quad& q : scenes::tessellate_disc({0, -2, 0}, {0, 1, 0}, 0.0, 4.0, 4)) {
    writer.polygon(q);
  }
  const std::string s = text.str();
  std::size_t triangles = 0;
  for (std::size_t at = s.find("p 3\n"); at != std::string::npos; at = s.find("p 3\n", at + 1)) {
    ++triangles;
  }
  EXPECT_EQ(triangles, 16U);
  EXPECT_EQ(s.find("p 4"), std::string::npos);
}

// ---- tessellated-mode totals (§4's table) --------------------------------------------------

// Counts `pp` and `p` entities of a stream without keeping it (lattice -t 4 is ~100 MB).
class EntityCounter : public std::streambuf {
 public:
  long patches = 0;
  long polygons = 0;

 protected:
  int overflow(int ch) override {
    if (ch != traits_type::eof()) feed(static_cast<char>(ch));
    return ch;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    for (std::streamsize i = 0; i < n; ++i) feed(s[i]);
    return n;
  }

 private:
  void feed(char ch) {
    if (ch == '\n') {
      if (prefix_ == "pp ") ++patches;
      if (prefix_.rfind("p ", 0) == 0) ++polygons;
      prefix_.clear();
    } else if (prefix_.size() < 3) {
      prefix_.push_back(ch);
    }
  }
  std::string prefix_;
};

struct TessellatedTotal {
  const char* scene;
  void (*generate)(int, scenes::NffWriter&);
  int size;  // the SPD default
  int res;   // the -t resolution
  long patches;
  long polygons;
};

void PrintTo(const TessellatedTotal& row, std::ostream* os) {
  *os << row.scene << " -s " << row.size << " -t " << row.res;
}

class TessellatedMode : public ::testing::TestWithParam<TessellatedTotal> {};

TEST_P(TessellatedMode, TotalsOfSection4) {
  const TessellatedTotal& row = GetParam();
  EntityCounter counter;
  std::ostream out(&counter);
  scenes::NffWriter writer(out, scenes::OutputMode::tessellated, row.res);
  row.generate(row.size, writer);
  EXPECT_EQ(counter.patches, row.patches);
  EXPECT_EQ(counter.polygons, row.polygons);
}

INSTANTIATE_TEST_SUITE_P(
    ExtraScenes, TessellatedMode,
    ::testing::Values(
        TessellatedTotal{"lattice", scenes::generate_lattice, 12, 3, 383292, 0},
        TessellatedTotal{"lattice", scenes::generate_lattice, 12, 4, 616512, 0},
        // shells' own -t takes no number: it is always resolution 3 (§2.1).
        TessellatedTotal{"shells", scenes::generate_shells, 5, 3, 622188, 0},
        // jacks forces resolution 2 whatever -t says.
        TessellatedTotal{"jacks", scenes::generate_jacks, 1, 3, 336, 0},
        TessellatedTotal{"jacks", scenes::generate_jacks, 1, 4, 336, 0},
        TessellatedTotal{"sample", scenes::generate_sample, 1, 3, 888, 16},
        TessellatedTotal{"sample", scenes::generate_sample, 1, 4, 1568, 16},
        // Already triangles: the height field and the NURBS patch (forced resolution 5).
        TessellatedTotal{"sombrero", scenes::generate_sombrero, 1, 4, 0, 1922},
        TessellatedTotal{"nurbtst", scenes::generate_nurbtst, 1, 4, 1500, 0}),
    [](const ::testing::TestParamInfo<TessellatedTotal>& row) {
      return std::string(row.param.scene) + "_t" + std::to_string(row.param.res);
    });

TEST(TessellatedOutput, Deterministic) {
  auto run = [] {
    std::ostringstream text;
    scenes::NffWriter writer(text, scenes::OutputMode::tessellated, 3);
    scenes::generate_jacks(2, writer);
    scenes::generate_sample(1, writer);
    return text.str();
  };
  EXPECT_EQ(run(), run());
}

}  // namespace
}  // namespace raygate::test

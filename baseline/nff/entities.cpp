// The NFF reader's entities other than the view (spd-spec.md §1.2): background, lights,
// materials and the four primitives, with the checks that keep degenerate geometry (which no
// tracer can intersect sensibly) out of the scene.
#include <algorithm>
#include <climits>
#include <cmath>
#include <utility>

#include "geom/triangulate.h"
#include "nff/reader.h"

namespace raygate::nff::detail {
namespace {

// A vertex count comes from the file, so it only bounds what is reserved up front; more memory
// is taken as vertices are actually read. `p 2000000000` thus fails at end of file cheaply.
constexpr long long kMaxReserve = 1024;

// Relative size below which a polygon counts as having no area. Genuinely thin SPD polygons
// are many orders of magnitude above it; collinear points rounded by "%g" are far below.
constexpr double kFlatness = 1e-12;

std::size_t distinct_vertex_count(const std::vector<Vec3>& vertices) {
  const Vec3& first = vertices.front();
  std::size_t second = 1;
  while (second < vertices.size() && vertices[second] == first) ++second;
  if (second == vertices.size()) return 1;
  for (std::size_t i = second + 1; i < vertices.size(); ++i) {
    if (!(vertices[i] == first) && !(vertices[i] == vertices[second])) return 3;
  }
  return 2;
}

// The vertex farthest from the first one, which sets the polygon's scale for the flatness tests.
struct Extent {
  Vec3 far;
  double squared = 0.0;  // its squared distance from the first vertex
};

Extent extent(const std::vector<Vec3>& vertices) {
  Extent e{vertices.front(), 0.0};
  for (const Vec3& v : vertices) {
    const double d = dot(v - vertices.front(), v - vertices.front());
    if (d > e.squared) e = {v, d};
  }
  return e;
}

// True when every vertex lies on the line through the first vertex and the farthest one,
// within kFlatness relative to the polygon's size.
bool all_collinear(const std::vector<Vec3>& vertices, const Extent& e) {
  const Vec3 axis = e.far - vertices.front();
  for (const Vec3& v : vertices) {
    if (length(cross(v - vertices.front(), axis)) > kFlatness * e.squared) return false;
  }
  return true;
}

}  // namespace

void Reader::read_background() { scene_.background = colour({.entity = "background (b)"}); }

// `l X Y Z [R G B]`: a number after the position can only be the optional colour, because no
// keyword is numeric (spd-spec.md §1.6).
void Reader::read_light() {
  Light light;
  light.position = vector({.entity = "light (l)", .part = "position"});
  if (is_number(lexer_.peek().text)) {
    light.color = colour({.entity = "light (l)", .part = "colour"});
    light.has_color = true;
  }
  scene_.lights.push_back(light);
}

void Reader::read_material(const Token& keyword) {
  constexpr std::string_view entity = "fill material (f)";
  Material material;
  material.loc = loc(keyword);
  material.color = colour({.entity = entity});
  material.kd = number({.entity = entity, .part = "Kd"});
  material.ks = number({.entity = entity, .part = "Ks"});
  material.shine = number({.entity = entity, .part = "Shine"});
  material.transmittance = number({.entity = entity, .part = "T"});
  material.ior = number({.entity = entity, .part = "ior"});
  scene_.materials.push_back(std::move(material));
}

int Reader::material_for(const Token& keyword) const {
  if (scene_.materials.empty()) fail(keyword, "a fill material (f) before the first object");
  return static_cast<int>(scene_.materials.size() - 1);
}

void Reader::read_sphere(const Token& keyword) {
  constexpr std::string_view entity = "sphere (s)";
  Sphere sphere;
  sphere.material = material_for(keyword);
  sphere.loc = loc(keyword);
  sphere.center = vector({.entity = entity, .part = "centre"});
  Token radius;
  sphere.radius = number({.entity = entity, .part = "radius"}, &radius);
  if (sphere.radius == 0.0) fail(radius, "a non-zero radius of sphere (s)");
  scene_.spheres.push_back(std::move(sphere));
}

// Both radii negative means inside-visible (kept); mixed signs or two zeros describe no
// surface, and coincident ends no axis.
void Reader::read_cone(const Token& keyword) {
  constexpr std::string_view entity = "cone (c)";
  Cone cone;
  cone.material = material_for(keyword);
  cone.loc = loc(keyword);
  Token base_radius;
  Token apex;
  Token apex_radius;
  cone.base = vector({.entity = entity, .part = "base"});
  cone.base_radius = number({.entity = entity, .part = "base radius"}, &base_radius);
  cone.apex = vector({.entity = entity, .part = "apex"}, &apex);
  cone.apex_radius = number({.entity = entity, .part = "apex radius"}, &apex_radius);
  if (cone.apex == cone.base) {
    fail_with(apex, "expected the apex of cone (c) away from its base, found the same point");
  }
  const std::string radii = describe(base_radius) + " and " + describe(apex_radius);
  if (cone.base_radius == 0.0 && cone.apex_radius == 0.0) {
    fail_with(apex_radius, "expected a non-zero radius of cone (c), found " + radii);
  }
  if ((cone.base_radius < 0.0 && cone.apex_radius > 0.0) ||
      (cone.base_radius > 0.0 && cone.apex_radius < 0.0)) {
    fail_with(apex_radius, "expected radii of cone (c) of the same sign, found " + radii);
  }
  scene_.cones.push_back(std::move(cone));
}

long long Reader::read_vertex_count(std::string_view entity) {
  const Token token = lexer_.next();
  long long count = 0;
  const Field field{.entity = entity, .part = "vertex count"};
  if (!parse_integer(token.text, count) || count < 3) {
    fail(token, field.words() + " as an integer of at least 3");
  }
  if (count > INT_MAX) fail(token, field.words() + " as an integer of at most 2147483647");
  return count;
}

void Reader::read_polygon(const Token& keyword) {
  constexpr std::string_view entity = "polygon (p)";
  Polygon polygon;
  polygon.material = material_for(keyword);
  polygon.loc = loc(keyword);
  const long long count = read_vertex_count(entity);
  polygon.vertices.reserve(static_cast<std::size_t>(std::min(count, kMaxReserve)));
  for (long long i = 1; i <= count; ++i) {
    polygon.vertices.push_back(vector({.entity = entity, .vertex = i, .count = count}));
  }
  check_polygon(keyword, entity, polygon.vertices);
  scene_.polygons.push_back(std::move(polygon));
}

void Reader::read_patch(const Token& keyword) {
  constexpr std::string_view entity = "patch (pp)";
  Patch patch;
  patch.material = material_for(keyword);
  patch.loc = loc(keyword);
  const long long count = read_vertex_count(entity);
  const auto reserve = static_cast<std::size_t>(std::min(count, kMaxReserve));
  patch.vertices.reserve(reserve);
  patch.normals.reserve(reserve);
  for (long long i = 1; i <= count; ++i) {
    patch.vertices.push_back(vector({.entity = entity, .vertex = i, .count = count}));
    const Field normal{.entity = entity, .part = "normal", .vertex = i, .count = count};
    Token at;
    const Vec3 n = vector(normal, &at);
    // Zero (or so small that its square underflows) cannot be normalised.
    if (dot(n, n) == 0.0) {
      fail_with(at, "expected " + normal.words("a non-zero ") + ", found a zero vector");
    }
    patch.normals.push_back(n);
  }
  // No shape check for patches: the SPD writes them uncleaned (spd-spec.md §1.5), and its own
  // teapot at size 1 and tessellated cones with a zero radius contain zero-area triangles. They
  // are legal input; the tracer counts them as degenerate and never hits them.
  scene_.patches.push_back(std::move(patch));
}

// Reported at the keyword: the fault is the polygon as a whole, not one number.
void Reader::check_polygon(const Token& keyword, std::string_view entity,
                           const std::vector<Vec3>& vertices) const {
  const std::string name(entity);
  const std::size_t distinct = distinct_vertex_count(vertices);
  if (distinct < 3) {
    fail_with(keyword, "expected at least 3 distinct vertices in " + name + ", found " +
                           std::to_string(distinct));
  }
  const Extent size = extent(vertices);
  if (all_collinear(vertices, size)) {
    fail_with(keyword, "expected " + name + " with non-zero area, found collinear vertices");
  }
  // Not collinear but no net area: a figure eight whose halves cancel.
  if (!(length(polygon_area_normal(vertices)) > kFlatness * size.squared)) {
    fail_with(keyword, "expected " + name + " with non-zero area, found a net area of zero");
  }
}

}  // namespace raygate::nff::detail

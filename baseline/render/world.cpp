// Building the World from an NFF scene, and the brute-force ray queries over it.
#include "render/world.h"

#include <array>
#include <cmath>
#include <string>

#include "geom/triangulate.h"
#include "render/intersect.h"

namespace raygate::render {
namespace {

ShadingMaterial make_material(const nff::Material& m) {
  ShadingMaterial out;
  out.color = m.color;
  out.kd = m.kd;
  out.ks = m.ks;
  out.shine = std::isfinite(m.shine) && m.shine >= 1.0 ? m.shine : 1.0;
  out.transmittance = m.transmittance;
  out.ior = std::isfinite(m.ior) && m.ior > 0.0 ? m.ior : 1.0;
  return out;
}

void add_patch(const nff::Patch& patch, World& world) {
  const std::size_t count = patch.vertices.size();
  if (count < 3 || patch.normals.size() != count) {
    ++world.degenerate_primitives;
    return;
  }
  std::vector<std::array<int, 3>> triangles;
  if (count == 3) {
    triangles.push_back({0, 1, 2});
  } else {
    triangles = triangulate_polygon(patch.vertices);
  }
  for (const auto& corner : triangles) {
    const Vec3 vertices[3] = {patch.vertices[corner[0]], patch.vertices[corner[1]],
                              patch.vertices[corner[2]]};
    const Vec3 normals[3] = {patch.normals[corner[0]], patch.normals[corner[1]],
                             patch.normals[corner[2]]};
    TrianglePrim triangle;
    if (make_triangle(vertices, normals, patch.material, triangle)) {
      world.triangles.push_back(triangle);
    } else {
      ++world.degenerate_primitives;
    }
  }
}

void check_materials(const nff::Scene& scene) {
  const int count = static_cast<int>(scene.materials.size());
  auto check = [count](int material, const nff::FileLoc& loc) {
    if (material < 0 || material >= count) {
      throw SceneError("the object at line " + std::to_string(loc.line) + " refers to material " +
                       std::to_string(material) + ", but the scene has " + std::to_string(count));
    }
  };
  for (const auto& s : scene.spheres) check(s.material, s.loc);
  for (const auto& c : scene.cones) check(c.material, c.loc);
  for (const auto& p : scene.polygons) check(p.material, p.loc);
  for (const auto& p : scene.patches) check(p.material, p.loc);
}

void add_geometry(const nff::Scene& scene, World& world) {
  for (const nff::Sphere& s : scene.spheres) {
    SpherePrim prim;
    if (make_sphere(s.center, s.radius, s.material, prim)) {
      world.spheres.push_back(prim);
    } else {
      ++world.degenerate_primitives;
    }
  }
  for (const nff::Cone& c : scene.cones) {
    ConePrim prim;
    if (make_cone(c.base, c.base_radius, c.apex, c.apex_radius, c.material, prim)) {
      world.cones.push_back(prim);
    } else {
      ++world.degenerate_primitives;
    }
  }
  for (const nff::Polygon& p : scene.polygons) {
    PolygonPrim prim;
    if (make_polygon(p.vertices, p.material, prim, world.polygon_points)) {
      world.polygons.push_back(prim);
      world.polygon_boxes.push_back(padded(bounds(p.vertices), kBoxPaddingRelative));
    } else {
      ++world.degenerate_primitives;
    }
  }
  for (const nff::Patch& p : scene.patches) add_patch(p, world);
}

void add_boxes(World& world) {
  for (const SpherePrim& s : world.spheres) {
    world.sphere_boxes.push_back(padded(bounds(s), kBoxPaddingRelative));
  }
  for (const ConePrim& c : world.cones) {
    world.cone_boxes.push_back(padded(bounds(c), kBoxPaddingRelative));
  }
  for (const TrianglePrim& t : world.triangles) {
    world.triangle_boxes.push_back(padded(bounds(t), kBoxPaddingRelative));
  }
}

// One kind's loop. kBoxes selects the control mode at compile time; the exact test and the
// strict `t < best` update (lowest index wins ties) are shared by both instantiations.
template <bool kBoxes, class Prim, class Test>
void scan_nearest(const std::vector<Prim>& prims, const std::vector<Aabb>& boxes,
                  const SlabRay& slab, double t_min, double& t_best, PrimKind kind, Hit& hit,
                  bool& found, TestCounters& counters, Test&& test) {
  const int count = static_cast<int>(prims.size());
  for (int i = 0; i < count; ++i) {
    if constexpr (kBoxes) {
      ++counters.bbox_tests;
      if (!hits_box(boxes[i], slab, t_min, t_best)) continue;
    }
    ++counters.primitive_tests;
    PrimHit candidate;
    if (test(prims[i], t_best, candidate)) {
      t_best = candidate.t;
      hit = {candidate.t, kind, i, candidate.b1, candidate.b2};
      found = true;
    }
  }
}

template <bool kBoxes>
bool nearest_in(const World& w, const Ray& ray, double t_min, double t_max, Hit& hit,
                TestCounters& counters) {
  const SlabRay slab = make_slab_ray(ray);
  double t_best = t_max;
  bool found = false;
  auto test = [&](const auto& prim, double t_limit, PrimHit& out) {
    return intersect(prim, ray, t_min, t_limit, out);
  };
  auto test_polygon = [&](const PolygonPrim& prim, double t_limit, PrimHit& out) {
    return intersect(prim, w.polygon_points, ray, t_min, t_limit, out);
  };
  scan_nearest<kBoxes>(w.spheres, w.sphere_boxes, slab, t_min, t_best, PrimKind::sphere, hit, found,
                       counters, test);
  scan_nearest<kBoxes>(w.cones, w.cone_boxes, slab, t_min, t_best, PrimKind::cone, hit, found,
                       counters, test);
  scan_nearest<kBoxes>(w.polygons, w.polygon_boxes, slab, t_min, t_best, PrimKind::polygon, hit,
                       found, counters, test_polygon);
  scan_nearest<kBoxes>(w.triangles, w.triangle_boxes, slab, t_min, t_best, PrimKind::triangle, hit,
                       found, counters, test);
  return found;
}

template <bool kBoxes, class Prim, class Test>
bool scan_any(const std::vector<Prim>& prims, const std::vector<Aabb>& boxes, const SlabRay& slab,
              double t_max, TestCounters& counters, Test&& test) {
  for (std::size_t i = 0; i < prims.size(); ++i) {
    if constexpr (kBoxes) {
      ++counters.bbox_tests;
      if (!hits_box(boxes[i], slab, 0.0, t_max)) continue;
    }
    ++counters.primitive_tests;
    PrimHit ignored;
    if (test(prims[i], ignored)) return true;
  }
  return false;
}

template <bool kBoxes>
bool occluded_in(const World& w, const Ray& ray, double t_max, TestCounters& counters) {
  const SlabRay slab = make_slab_ray(ray);
  auto test = [&](const auto& prim, PrimHit& out) { return intersect(prim, ray, 0.0, t_max, out); };
  auto test_polygon = [&](const PolygonPrim& prim, PrimHit& out) {
    return intersect(prim, w.polygon_points, ray, 0.0, t_max, out);
  };
  return scan_any<kBoxes>(w.spheres, w.sphere_boxes, slab, t_max, counters, test) ||
         scan_any<kBoxes>(w.cones, w.cone_boxes, slab, t_max, counters, test) ||
         scan_any<kBoxes>(w.polygons, w.polygon_boxes, slab, t_max, counters, test_polygon) ||
         scan_any<kBoxes>(w.triangles, w.triangle_boxes, slab, t_max, counters, test);
}

}  // namespace

World build_world(const nff::Scene& scene) {
  World world;
  world.background = scene.background;
  for (const nff::Material& m : scene.materials) world.materials.push_back(make_material(m));
  // The SPD exporters' convention: each of n lights has intensity 1/sqrt(n).
  const double per_light =
      scene.lights.empty() ? 0.0 : 1.0 / std::sqrt(double(scene.lights.size()));
  for (const nff::Light& l : scene.lights) {
    world.lights.push_back({l.position, l.color * per_light});
  }
  check_materials(scene);
  add_geometry(scene, world);
  add_boxes(world);
  return world;
}

bool find_nearest(const World& world, Accel accel, const Ray& ray, double t_min, double t_max,
                  Hit& hit, TestCounters& counters) {
  return accel == Accel::bbox ? nearest_in<true>(world, ray, t_min, t_max, hit, counters)
                              : nearest_in<false>(world, ray, t_min, t_max, hit, counters);
}

bool is_occluded(const World& world, Accel accel, const Ray& ray, double t_max,
                 TestCounters& counters) {
  return accel == Accel::bbox ? occluded_in<true>(world, ray, t_max, counters)
                              : occluded_in<false>(world, ray, t_max, counters);
}

}  // namespace raygate::render

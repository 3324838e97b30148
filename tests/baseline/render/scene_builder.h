// Building nff::Scene values in code for the tracer's tests, so each test states its geometry
// where the expected numbers are derived.
#pragma once

#include <vector>

#include "geom/vec3.h"
#include "nff/scene.h"

namespace raygate::test {

inline nff::Scene make_scene(Vec3 from, Vec3 at, Vec3 up, double angle_degrees, int width,
                             int height, Vec3 background = {}) {
  nff::Scene scene;
  scene.path = "test";
  scene.background = background;
  scene.view.from = from;
  scene.view.at = at;
  scene.view.up = up;
  scene.view.angle_degrees = angle_degrees;
  scene.view.hither = 0.0;
  scene.view.width = width;
  scene.view.height = height;
  return scene;
}

struct MaterialSpec {
  Vec3 color{1.0, 1.0, 1.0};
  double kd = 0.0;
  double ks = 0.0;
  double shine = 1.0;
  double transmittance = 0.0;
  double ior = 1.0;
};

inline int add_material(nff::Scene& scene, const MaterialSpec& m) {
  nff::Material material;
  material.color = m.color;
  material.kd = m.kd;
  material.ks = m.ks;
  material.shine = m.shine;
  material.transmittance = m.transmittance;
  material.ior = m.ior;
  scene.materials.push_back(material);
  return static_cast<int>(scene.materials.size()) - 1;
}

inline void add_light(nff::Scene& scene, Vec3 position) {
  nff::Light light;
  light.position = position;
  scene.lights.push_back(light);
}

inline void add_sphere(nff::Scene& scene, Vec3 center, double radius, int material) {
  nff::Sphere s;
  s.center = center;
  s.radius = radius;
  s.material = material;
  scene.spheres.push_back(s);
}

inline void add_cone(nff::Scene& scene, Vec3 base, double base_radius, Vec3 apex,
                     double apex_radius, int material) {
  nff::Cone c;
  c.base = base;
  c.base_radius = base_radius;
  c.apex = apex;
  c.apex_radius = apex_radius;
  c.material = material;
  scene.cones.push_back(c);
}

inline void add_polygon(nff::Scene& scene, std::vector<Vec3> vertices, int material) {
  nff::Polygon p;
  p.vertices = std::move(vertices);
  p.material = material;
  scene.polygons.push_back(std::move(p));
}

inline void add_patch(nff::Scene& scene, std::vector<Vec3> vertices, std::vector<Vec3> normals,
                      int material) {
  nff::Patch p;
  p.vertices = std::move(vertices);
  p.normals = std::move(normals);
  p.material = material;
  scene.patches.push_back(std::move(p));
}

// An axis-aligned square in the plane z = height, counter-clockwise seen from +z.
inline std::vector<Vec3> square_z(double x0, double y0, double x1, double y1, double height) {
  return {{x0, y0, height}, {x1, y0, height}, {x1, y1, height}, {x0, y1, height}};
}

}  // namespace raygate::test

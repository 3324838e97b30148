// pbrt-v4 scene from an NFF scene (docs/scene-formats.md). pbrt-v4 is left-handed:
// `Scale -1 1 1` before `LookAt` makes the right-handed NFF scene appear unmirrored. Its lights
// and materials are physically based, so the NFF shading is approximated (documented there).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <ostream>

#include "writers/scene_geometry.h"
#include "writers/scene_writers.h"
#include "writers/text.h"

namespace raygate::writers {
namespace {

constexpr int kMaxDepth = 5;       // the baseline's default depth limit
constexpr int kPixelSamples = 16;  // pbrt-v4's default

std::string floats(std::initializer_list<double> values) {
  std::string text = "[";
  for (double v : values) text += " " + num(v);
  return text + " ]";
}

std::string rgb(const Vec3& c) {
  return "[ " + num(std::clamp(c.x, 0.0, 1.0)) + " " + num(std::clamp(c.y, 0.0, 1.0)) + " " +
         num(std::clamp(c.z, 0.0, 1.0)) + " ]";
}

std::string material_name(int index) { return "f" + std::to_string(index + 1); }

// pbrt's `fov` spans the shorter image side; NFF's `angle` spans the width.
double pbrt_fov(const nff::View& view, const CameraBasis& c) {
  if (view.width <= view.height) return view.angle_degrees;
  return 2.0 * std::atan(c.half_height) * 180.0 / std::numbers::pi;
}

void write_options(const nff::Scene& scene, std::ostream& out, std::string_view image_name) {
  const nff::View& v = scene.view;
  const CameraBasis c = camera_basis(v);
  out << "# pbrt-v4 scene converted from " << source_name(scene.path)
      << " by raygate (docs/scene-formats.md); shading is approximated.\n"
      << "Scale -1 1 1  # pbrt-v4 is left-handed: show the right-handed NFF scene unmirrored\n"
      << "LookAt " << vec(v.from, " ") << "  " << vec(v.at, " ") << "  " << vec(v.up, " ") << "\n"
      << "Camera \"perspective\" \"float fov\" " << floats({pbrt_fov(v, c)}) << "\n"
      << "Film \"rgb\" \"integer xresolution\" [ " << v.width << " ] \"integer yresolution\" [ "
      << v.height << " ] \"string filename\" [ \"" << image_name << "\" ]\n"
      << "Sampler \"zsobol\" \"integer pixelsamples\" [ " << kPixelSamples << " ]\n"
      << "Integrator \"path\" \"integer maxdepth\" [ " << kMaxDepth << " ]\n"
      << "WorldBegin\n";
}

// The background as an infinite light (pbrt shows it where rays escape; it also lights the
// scene a little, like an ambient term). Point lights fall off as 1/d^2 in pbrt: their scale
// gives the baseline's diffuse brightness at the look-at point (the diffuse BRDF is R/pi).
void write_lights(const nff::Scene& scene, std::ostream& out) {
  const Vec3& b = scene.background;
  if (b.x > 0.0 || b.y > 0.0 || b.z > 0.0) {
    out << "LightSource \"infinite\" \"rgb L\" [ " << vec(b, " ") << " ]\n";
  }
  const double intensity = light_intensity(scene.lights.size());
  for (const nff::Light& light : scene.lights) {
    const Vec3 d = scene.view.at - light.position;
    const double scale = std::numbers::pi * dot(d, d) * intensity;
    out << "LightSource \"point\" \"point3 from\" [ " << vec(light.position, " ")
        << " ] \"rgb I\" [ " << vec(light.color, " ") << " ] \"float scale\" " << floats({scale})
        << "\n";
  }
}

// Transmitters: dielectric. Diffuse only: diffuse. Mirror only: conductor. Both: a mix that
// picks the diffuse part (reflectance (Kd+Ks)·C) with probability Kd/(Kd+Ks) and the mirror
// (reflectance Kd+Ks) otherwise, so on average each contributes its NFF weight.
void write_material(const nff::Material& m, int index, std::ostream& out) {
  const std::string name = material_name(index);
  const std::string make = "MakeNamedMaterial \"";
  if (m.transmittance > 0.0) {
    out << make << name << "\" \"string type\" \"dielectric\" \"float eta\" "
        << floats({m.ior > 0.0 ? m.ior : 1.0}) << "\n";
  } else if (m.ks <= 0.0) {
    out << make << name << "\" \"string type\" \"diffuse\" \"rgb reflectance\" "
        << rgb(m.color * m.kd) << "\n";
  } else if (m.kd <= 0.0) {
    out << make << name << "\" \"string type\" \"conductor\" \"rgb reflectance\" "
        << rgb({m.ks, m.ks, m.ks}) << " \"float roughness\" [ 0 ]\n";
  } else {
    const double sum = m.kd + m.ks;
    out << make << name << "-diffuse\" \"string type\" \"diffuse\" \"rgb reflectance\" "
        << rgb(m.color * sum) << "\n"
        << make << name << "-mirror\" \"string type\" \"conductor\" \"rgb reflectance\" "
        << rgb({sum, sum, sum}) << " \"float roughness\" [ 0 ]\n"
        << make << name << "\" \"string type\" \"mix\" \"string materials\" [ \"" << name
        << "-diffuse\" \"" << name << "-mirror\" ] \"float amount\" " << floats({m.ks / sum})
        << "\n";
  }
}

// Switches the current material only when it changes (it is graphics state in pbrt).
class MaterialState {
 public:
  void use(int material, std::ostream& out) {
    if (material == current_) return;
    current_ = material;
    out << "NamedMaterial \"" << material_name(material) << "\"\n";
  }

 private:
  int current_ = -1;
};

void write_triangle_mesh(const Mesh& mesh, std::ostream& out) {
  out << "Shape \"trianglemesh\"\n  \"point3 P\" [";
  for (const Vec3& p : mesh.positions) out << " " << vec(p, " ");
  bool normals = !mesh.normals.empty();
  for (const Vec3& n : mesh.normals) normals = normals && length(n) > 0.0;
  if (normals) {
    out << " ]\n  \"normal N\" [";
    for (const Vec3& n : mesh.normals) out << " " << vec(n, " ");
  }
  out << " ]\n  \"integer indices\" [";
  for (const std::array<int, 3>& t : mesh.triangles)
    out << " " << t[0] << " " << t[1] << " " << t[2];
  out << " ]\n";
}

void write_sphere(const nff::Sphere& s, std::ostream& out) {
  out << "AttributeBegin\n  Translate " << vec(s.center, " ")
      << "\n  Shape \"sphere\" \"float radius\" " << floats({std::fabs(s.radius)})
      << "\nAttributeEnd\n";
}

// pbrt-v4's cylinder runs along z from zmin to zmax; the transform's columns are the frame
// around the axis and the base point. pbrt-v4 has no cone: those are triangle meshes.
void write_cone(const nff::Cone& c, int segments, std::ostream& out) {
  if (std::fabs(c.base_radius) != std::fabs(c.apex_radius)) {
    write_triangle_mesh(cone_mesh(c, segments), out);
    return;
  }
  const double height = length(c.apex - c.base);
  const Frame f = frame_around((c.apex - c.base) / height);
  out << "AttributeBegin\n  ConcatTransform [ " << vec(f.u, " ") << " 0  " << vec(f.v, " ")
      << " 0  " << vec(f.w, " ") << " 0  " << vec(c.base, " ") << " 1 ]\n"
      << "  Shape \"cylinder\" \"float radius\" " << floats({std::fabs(c.base_radius)})
      << " \"float zmin\" [ 0 ] \"float zmax\" " << floats({height}) << "\nAttributeEnd\n";
}

}  // namespace

void write_pbrt(const nff::Scene& scene, std::ostream& out, std::string_view image_name,
                const WriteOptions& options) {
  check_segments(options.segments);
  write_options(scene, out, image_name);
  write_lights(scene, out);
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    write_material(scene.materials[i], static_cast<int>(i), out);
  }
  MaterialState state;
  std::size_t skipped = 0;
  for (const nff::Sphere& s : scene.spheres) {
    if (is_degenerate(s)) {
      ++skipped;
      continue;
    }
    state.use(s.material, out);
    write_sphere(s, out);
  }
  for (const nff::Cone& c : scene.cones) {
    if (is_degenerate(c)) {
      ++skipped;
      continue;
    }
    state.use(c.material, out);
    write_cone(c, options.segments, out);
  }
  auto write_mesh = [&](const Mesh& mesh, int material) {
    if (mesh.triangles.empty()) {
      ++skipped;
      return;
    }
    state.use(material, out);
    write_triangle_mesh(mesh, out);
  };
  for (const nff::Polygon& p : scene.polygons) write_mesh(polygon_mesh(p), p.material);
  for (const nff::Patch& p : scene.patches) write_mesh(patch_mesh(p), p.material);
  out << "# " << skipped << " degenerate primitive(s) skipped\n";
}

}  // namespace raygate::writers

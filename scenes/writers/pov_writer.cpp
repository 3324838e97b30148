// POV-Ray 3.7 SDL from an NFF scene (docs/scene-formats.md). The camera is given as
// explicit location/direction/right/up vectors in world space, so every eye ray is the baseline's
// and the right-handed scene appears unmirrored in left-handed POV-Ray.
#include <cmath>
#include <ostream>

#include "writers/scene_geometry.h"
#include "writers/scene_writers.h"
#include "writers/text.h"

namespace raygate::writers {
namespace {

// The baseline's depth limit (docs/baseline.md: --depth, default 5, eye ray at depth 1).
constexpr int kMaxTraceLevel = 5;
constexpr double kAmbient = 0.1;  // the baseline's ka

std::string pov(const Vec3& v) { return "<" + vec(v, ", ") + ">"; }
std::string pov_exact(const Vec3& v) { return "<" + vec(v, ", ", exact) + ">"; }

std::string material_name(int index) { return "F" + std::to_string(index + 1); }

void write_header(const nff::Scene& scene, std::ostream& out) {
  out << "// POV-Ray 3.7 scene converted from " << source_name(scene.path)
      << " by raygate (docs/scene-formats.md).\n"
      << "// Render at +W" << scene.view.width << " +H" << scene.view.height
      << " to frame it as raygate-baseline does.\n"
      << "#version 3.7;\n"
      << "global_settings { assumed_gamma 1.0 max_trace_level " << kMaxTraceLevel
      << " adc_bailout 0 }\n\n";
}

// direction + u*right + v*up with u, v in [-1/2, 1/2] across the image: the baseline's rays.
void write_camera(const nff::Scene& scene, std::ostream& out) {
  const CameraBasis c = camera_basis(scene.view);
  out << "camera {\n  perspective\n  location " << pov(scene.view.from) << "\n"
      << "  direction " << pov_exact(c.forward) << "\n"
      << "  right " << pov_exact(c.right * (2.0 * c.half_width)) << "\n"
      << "  up " << pov_exact(c.up * (2.0 * c.half_height)) << "\n}\n"
      << "background { color rgb " << pov(scene.background) << " }\n";
}

void write_lights(const nff::Scene& scene, std::ostream& out) {
  const double intensity = light_intensity(scene.lights.size());
  for (const nff::Light& light : scene.lights) {
    out << "light_source { " << pov(light.position) << " color rgb " << pov(light.color * intensity)
        << " }\n";
  }
}

// POV-Ray weights a surface's own light (ambient, diffuse) by its opacity 1 - transmit; the
// baseline does not, so those terms are divided by the opacity to give the same pixel.
void write_material(const nff::Material& m, int index, std::ostream& out) {
  const bool transmits = m.transmittance > 0.0;
  const double opacity = transmits && m.transmittance < 1.0 ? 1.0 - m.transmittance : 1.0;
  out << "#declare " << material_name(index) << " = material {\n  texture {\n    pigment { ";
  if (transmits) {
    out << "rgbt <" << vec(m.color, ", ") << ", " << num(m.transmittance) << ">";
  } else {
    out << "rgb " << pov(m.color);
  }
  out << " }\n    finish { ambient " << num(kAmbient / opacity) << " diffuse "
      << num(m.kd / opacity);
  if (m.ks > 0.0) {
    const double shine = m.shine < 1.0 ? 1.0 : m.shine;  // clamped as the baseline does
    out << " phong " << num(m.ks) << " phong_size " << num(shine) << " reflection { " << num(m.ks)
        << " }";
  }
  out << " }\n  }\n";
  if (transmits) out << "  interior { ior " << num(m.ior > 0.0 ? m.ior : 1.0) << " }\n";
  out << "}\n";
}

std::string use(int material) { return " material { " + material_name(material) + " } }\n"; }

void write_mesh(const Mesh& mesh, int material, std::ostream& out) {
  for (const std::array<int, 3>& t : mesh.triangles) {
    bool smooth = !mesh.normals.empty();
    for (int i : t) smooth = smooth && length(mesh.normals[i]) > 0.0;
    out << (smooth ? "smooth_triangle { " : "triangle { ");
    for (int k = 0; k < 3; ++k) {
      out << (k > 0 ? ", " : "") << pov(mesh.positions[t[k]]);
      if (smooth) out << ", " << pov(mesh.normals[t[k]]);
    }
    out << use(material);
  }
}

}  // namespace

void write_pov(const nff::Scene& scene, std::ostream& out) {
  write_header(scene, out);
  write_camera(scene, out);
  write_lights(scene, out);
  out << "\n";
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    write_material(scene.materials[i], static_cast<int>(i), out);
  }
  out << "\n";
  std::size_t skipped = 0;
  for (const nff::Sphere& s : scene.spheres) {
    if (is_degenerate(s)) {
      ++skipped;
      continue;
    }
    out << "sphere { " << pov(s.center) << ", " << num(std::fabs(s.radius)) << use(s.material);
  }
  for (const nff::Cone& c : scene.cones) {
    if (is_degenerate(c)) {
      ++skipped;
      continue;
    }
    out << "cone { " << pov(c.base) << ", " << num(std::fabs(c.base_radius)) << ", " << pov(c.apex)
        << ", " << num(std::fabs(c.apex_radius)) << " open" << use(c.material);
  }
  for (const nff::Polygon& p : scene.polygons) {
    const Mesh mesh = polygon_mesh(p);
    skipped += mesh.triangles.empty() ? 1 : 0;
    write_mesh(mesh, p.material, out);
  }
  for (const nff::Patch& p : scene.patches) {
    const Mesh mesh = patch_mesh(p);
    skipped += mesh.triangles.empty() ? 1 : 0;
    write_mesh(mesh, p.material, out);
  }
  out << "// " << skipped << " degenerate primitive(s) skipped\n";
}

}  // namespace raygate::writers

// Wavefront OBJ + MTL from an NFF scene (docs/scene-formats.md). OBJ holds geometry and
// materials only: no camera, lights or background. Every NFF primitive becomes one `o` object
// with its own `usemtl`; spheres and cones are tessellated with vertex normals, polygons and
// patches split into triangles, patches keeping their normals.
#include <algorithm>
#include <ostream>

#include "writers/scene_geometry.h"
#include "writers/scene_writers.h"
#include "writers/text.h"

namespace raygate::writers {
namespace {

std::string material_name(int index) { return "f" + std::to_string(index + 1); }

// Vertex and normal numbers already used: OBJ indices are global and 1-based.
struct ObjCounters {
  std::size_t positions = 0;
  std::size_t normals = 0;
};

void write_object(const std::string& name, int material, const Mesh& mesh, ObjCounters& used,
                  std::ostream& out) {
  out << "o " << name << "\nusemtl " << material_name(material) << "\n";
  for (const Vec3& p : mesh.positions) out << "v " << vec(p, " ") << "\n";
  for (const Vec3& n : mesh.normals) out << "vn " << vec(n, " ") << "\n";
  const bool with_normals = !mesh.normals.empty();
  for (const std::array<int, 3>& t : mesh.triangles) {
    out << "f";
    for (int i : t) {
      out << " " << used.positions + static_cast<std::size_t>(i) + 1;
      if (with_normals) out << "//" << used.normals + static_cast<std::size_t>(i) + 1;
    }
    out << "\n";
  }
  used.positions += mesh.positions.size();
  used.normals += mesh.normals.size();
}

}  // namespace

void write_obj(const nff::Scene& scene, std::ostream& out, std::string_view mtl_name,
               const WriteOptions& options) {
  check_segments(options.segments);
  camera_basis(scene.view);  // the same views are refused in every format
  out << "# Wavefront OBJ converted from " << source_name(scene.path)
      << " by raygate (docs/scene-formats.md).\n"
      << "# Spheres and cones tessellated with " << options.segments
      << " segments; no camera or lights (OBJ has none).\n"
      << "mtllib " << mtl_name << "\n";
  ObjCounters used;
  std::size_t skipped = 0;
  for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
    const nff::Sphere& s = scene.spheres[i];
    if (is_degenerate(s)) {
      ++skipped;
      continue;
    }
    write_object("sphere" + std::to_string(i + 1), s.material, sphere_mesh(s, options.segments),
                 used, out);
  }
  for (std::size_t i = 0; i < scene.cones.size(); ++i) {
    const nff::Cone& c = scene.cones[i];
    if (is_degenerate(c)) {
      ++skipped;
      continue;
    }
    write_object("cone" + std::to_string(i + 1), c.material, cone_mesh(c, options.segments), used,
                 out);
  }
  for (std::size_t i = 0; i < scene.polygons.size(); ++i) {
    const Mesh mesh = polygon_mesh(scene.polygons[i]);
    if (mesh.triangles.empty()) {
      ++skipped;
      continue;
    }
    write_object("polygon" + std::to_string(i + 1), scene.polygons[i].material, mesh, used, out);
  }
  for (std::size_t i = 0; i < scene.patches.size(); ++i) {
    const Mesh mesh = patch_mesh(scene.patches[i]);
    if (mesh.triangles.empty()) {
      ++skipped;
      continue;
    }
    write_object("patch" + std::to_string(i + 1), scene.patches[i].material, mesh, used, out);
  }
  out << "# " << skipped << " degenerate primitive(s) skipped\n";
}

// Kd, Ks as the NFF weights times the colour (Ks white), Ka the baseline's 0.1 ambient, Ns the
// Phong exponent within MTL's 0..1000, d = 1 - T, Ni the ior, and illum 2 (highlight), 3 (plus
// mirror reflection) or 6 (plus refraction).
void write_mtl(const nff::Scene& scene, std::ostream& out) {
  out << "# Wavefront MTL converted from " << source_name(scene.path)
      << " by raygate (docs/scene-formats.md): one material per NFF `f`.\n";
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const nff::Material& m = scene.materials[i];
    const int illum = m.transmittance > 0.0 ? 6 : (m.ks > 0.0 ? 3 : 2);
    out << "\nnewmtl " << material_name(static_cast<int>(i)) << "\n"
        << "Ka " << vec(m.color * 0.1, " ") << "\n"
        << "Kd " << vec(m.color * m.kd, " ") << "\n"
        << "Ks " << vec(Vec3{m.ks, m.ks, m.ks}, " ") << "\n"
        << "Ns " << num(std::clamp(m.shine, 0.0, 1000.0)) << "\n"
        << "d " << num(1.0 - std::clamp(m.transmittance, 0.0, 1.0)) << "\n"
        << "Ni " << num(m.ior > 0.0 ? m.ior : 1.0) << "\n"
        << "illum " << illum << "\n";
  }
}

}  // namespace raygate::writers

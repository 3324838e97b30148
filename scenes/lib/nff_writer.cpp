#include "lib/nff_writer.h"

#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "lib/tessellate.h"

namespace raygate::scenes {

double shine_from_angle(double ang_degrees) {
  const double theta = std::numbers::pi * ang_degrees / 180.0;
  if (theta <= 0.0) return 100000.0;
  if (theta >= std::numbers::pi / 2.0) return 1.0;
  return std::log(0.5) / std::log(std::cos(theta));
}

std::string format_g(double value) {
  // std::to_chars in general format with precision 6 is printf("%g") without the locale.
  char buffer[64];
  const auto result =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, 6);
  if (result.ec != std::errc()) throw std::logic_error("format_g: buffer too small");
  return std::string(buffer, result.ptr);
}

NffWriter::NffWriter(std::ostream& out, OutputMode mode, int tessellation_resolution)
    : out_(out), mode_(mode), resolution_(tessellation_resolution) {
  if (resolution_ < 1) throw std::invalid_argument("tessellation resolution must be at least 1");
}

void NffWriter::write_vec(const Vec3& v) {
  out_ << format_g(v.x) << ' ' << format_g(v.y) << ' ' << format_g(v.z);
}

void NffWriter::background(const Vec3& color) {
  out_ << "b ";
  write_vec(color);
  out_ << '\n';
}

void NffWriter::view(const Vec3& from, const Vec3& at, const Vec3& up, double angle_degrees,
                     double hither, int width, int height) {
  out_ << "v\nfrom ";
  write_vec(from);
  out_ << "\nat ";
  write_vec(at);
  out_ << "\nup ";
  write_vec(up);
  out_ << "\nangle " << format_g(angle_degrees) << "\nhither " << format_g(hither)
       << "\nresolution " << (width_override_ > 0 ? width_override_ : width) << ' '
       << (height_override_ > 0 ? height_override_ : height) << '\n';
}

void NffWriter::light(const Vec3& position) {
  out_ << "l ";
  write_vec(position);
  out_ << '\n';
}

void NffWriter::material(const SpdMaterial& m) {
  out_ << "f ";
  write_vec(m.color);
  out_ << ' ' << format_g(m.kd) << ' ' << format_g(m.ks) << ' ' << format_g(shine_from_angle(m.ang))
       << ' ' << format_g(m.kt) << ' ' << format_g(m.ior) << '\n';
}

void NffWriter::sphere(const Vec3& center, double radius) {
  if (mode_ == OutputMode::tessellated) {
    for (const PatchTriangle& t : tessellate_sphere(center, radius, resolution_)) {
      patch(t.vertices, t.normals);
    }
    return;
  }
  out_ << "s ";
  write_vec(center);
  out_ << ' ' << format_g(radius) << '\n';
}

void NffWriter::cone(const Vec3& base, double base_radius, const Vec3& apex, double apex_radius) {
  if (mode_ == OutputMode::tessellated) {
    for (const PatchTriangle& t :
         tessellate_cone(base, base_radius, apex, apex_radius, resolution_)) {
      patch(t.vertices, t.normals);
    }
    return;
  }
  out_ << "c ";
  write_vec(base);
  out_ << ' ' << format_g(base_radius) << ' ';
  write_vec(apex);
  out_ << ' ' << format_g(apex_radius) << '\n';
}

void NffWriter::polygon(std::span<const Vec3> vertices) {
  constexpr double kMergeDistance = 1e-6;
  std::vector<Vec3> kept;
  kept.reserve(vertices.size());
  for (const Vec3& v : vertices) {
    if (kept.empty() || length(v - kept.back()) >= kMergeDistance) kept.push_back(v);
  }
  while (kept.size() > 1 && length(kept.back() - kept.front()) < kMergeDistance) kept.pop_back();
  if (kept.size() < 3) return;
  out_ << "p " << kept.size() << '\n';
  for (const Vec3& v : kept) {
    write_vec(v);
    out_ << '\n';
  }
}

void NffWriter::patch(std::span<const Vec3> vertices, std::span<const Vec3> normals) {
  if (vertices.size() != normals.size()) {
    throw std::invalid_argument("patch: one normal per vertex is required");
  }
  out_ << "pp " << vertices.size() << '\n';
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    write_vec(vertices[i]);
    out_ << ' ';
    write_vec(normals[i]);
    out_ << '\n';
  }
}

void NffWriter::line(const std::string& text) { out_ << text << '\n'; }

}  // namespace raygate::scenes

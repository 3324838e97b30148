// Writes NFF the way the SPD library does (spd-spec.md §1.5): numbers as C "%g" in the C locale,
// `b` first, then the view, the lights, and `f` lines interleaved with geometry; polygons are
// cleaned of repeated vertices; `c` on one line. Generators call it in the SPD's order, with
// the SPD's richer material, which it reduces to an NFF `f`.
#pragma once

#include <ostream>
#include <span>
#include <string>

#include "geom/vec3.h"

namespace raygate::scenes {

// The material as the SPD generators state it (spd-spec.md §1.4).
struct SpdMaterial {
  Vec3 color;
  double ka = 0.0;       // ambient (dropped by NFF)
  double kd = 0.0;       // diffuse
  double ks = 0.0;       // mirror reflection
  double ks_spec = 0.0;  // highlight weight (dropped by NFF)
  double ang = 0.0;      // degrees at which the highlight falls to 50%
  double kt = 0.0;       // transmission
  double ior = 1.0;
};

// The Phong exponent that NFF stores for a highlight half-angle: ln(0.5)/ln(cos θ), with the
// SPD's clamps (≤0° gives 100000, ≥90° gives 1).
double shine_from_angle(double ang_degrees);

// "%g" formatting: 6 significant digits, trailing zeros removed, C locale, "-0" kept.
std::string format_g(double value);

enum class OutputMode {
  curves,       // spheres and cones as such (the mode for ray-tracing tests)
  tessellated,  // every non-polygon primitive becomes `pp 3` triangles (spd-spec.md §4)
};

class NffWriter {
 public:
  // `tessellation_resolution` is used in tessellated mode, and for primitives NFF cannot hold.
  NffWriter(std::ostream& out, OutputMode mode = OutputMode::curves,
            int tessellation_resolution = 3);

  // Suites render SPD scenes smaller than the SPD's 512x512: the `resolution` line is written
  // with these values instead of the generator's (0 keeps the generator's).
  void override_resolution(int width, int height) {
    width_override_ = width;
    height_override_ = height;
  }

  OutputMode mode() const { return mode_; }
  int tessellation_resolution() const { return resolution_; }

  void background(const Vec3& color);
  void view(const Vec3& from, const Vec3& at, const Vec3& up, double angle_degrees, double hither,
            int width, int height);
  void light(const Vec3& position);
  void material(const SpdMaterial& material);

  void sphere(const Vec3& center, double radius);
  // Open cone or cylinder from base to apex.
  void cone(const Vec3& base, double base_radius, const Vec3& apex, double apex_radius);
  // `p N`, after removing consecutive vertices closer than 1e-6 (wrapping around); dropped
  // when fewer than 3 remain.
  void polygon(std::span<const Vec3> vertices);
  // `pp N` with a normal per vertex; written as given.
  void patch(std::span<const Vec3> vertices, std::span<const Vec3> normals);

  // Raw line access for the few entities that need it (the writer adds the newline).
  void line(const std::string& text);

 private:
  void write_vec(const Vec3& v);

  std::ostream& out_;
  OutputMode mode_;
  int resolution_;
  int width_override_ = 0;
  int height_override_ = 0;
};

}  // namespace raygate::scenes

// Whitted ray tracing over a World: ambient + Phong direct light with shadow rays, mirror
// reflection, Snell refraction with total internal reflection, a depth limit. The exact model
// and its conventions are in docs/baseline.md ("Shading").
#pragma once

#include <cstdint>

#include "geom/ray.h"
#include "render/surface.h"
#include "render/world.h"

namespace raygate::render {

// SPD's readnff assumes this ambient coefficient for every surface.
inline constexpr double kAmbient = 0.1;

struct RayCounts {
  std::uint64_t eye = 0;
  std::uint64_t eye_hits = 0;
  std::uint64_t shadow = 0;
  std::uint64_t reflection = 0;
  std::uint64_t refraction = 0;
  // Transmitting hits below the depth limit where no refraction ray could be spawned (not rays;
  // counted to explain differences from published refraction counts, docs/validation.md).
  std::uint64_t total_internal_reflections = 0;
};

struct TraceSettings {
  Accel accel = Accel::none;
  int max_depth = 5;  // the eye ray is depth 1
};

// The secondary rays a hit spawns (before the depth limit is applied). A pure function of the
// hit, shared by the tracer and the tests that follow a ray through glass.
struct SecondaryRays {
  bool reflects = false;  // Ks > 0 or T > 0
  Ray reflected;
  double reflection_weight = 0.0;  // Ks, plus T on total internal reflection
  bool refracts = false;           // T > 0 and no total internal reflection
  Ray refracted;
};

SecondaryRays spawn_secondary(const Ray& incoming, const SurfacePoint& surface,
                              const ShadingMaterial& material);

class Tracer {
 public:
  Tracer(const World& world, const TraceSettings& settings, RayCounts& rays, TestCounters& tests)
      : world_(world), settings_(settings), rays_(rays), tests_(tests) {}

  // Radiance along an eye ray (depth 1); t_min comes from the hither plane.
  Vec3 trace_eye(const Ray& ray, double t_min);

  // Radiance along any ray at the given depth (1-based). Public so tests can follow a
  // secondary ray on its own.
  Vec3 trace(const Ray& ray, double t_min, int depth);

 private:
  Vec3 shade(const Ray& ray, const Hit& hit, int depth);
  Vec3 direct_light(const SurfacePoint& surface, const Vec3& normal, const Vec3& to_viewer,
                    const Vec3& shadow_origin, const ShadingMaterial& material);

  const World& world_;
  TraceSettings settings_;
  RayCounts& rays_;
  TestCounters& tests_;
};

}  // namespace raygate::render

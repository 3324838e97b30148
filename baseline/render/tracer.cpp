// The Whitted shading rules of spd-spec.md §1.4, as stated in docs/baseline.md.
#include "render/tracer.h"

#include <cmath>
#include <limits>

namespace raygate::render {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

}  // namespace

Vec3 Tracer::trace_eye(const Ray& ray, double t_min) {
  ++rays_.eye;
  Hit hit;
  if (!find_nearest(world_, settings_.accel, ray, t_min, kInfinity, hit, tests_)) {
    return world_.background;
  }
  ++rays_.eye_hits;
  return shade(ray, hit, 1);
}

Vec3 Tracer::trace(const Ray& ray, double t_min, int depth) {
  Hit hit;
  if (!find_nearest(world_, settings_.accel, ray, t_min, kInfinity, hit, tests_)) {
    return world_.background;
  }
  return shade(ray, hit, depth);
}

Vec3 Tracer::shade(const Ray& ray, const Hit& hit, int depth) {
  const SurfacePoint surface = evaluate_surface(world_, ray, hit);
  const ShadingMaterial& material = world_.materials[surface.material];
  const Facing facing = face_toward(surface, ray.direction);
  const Vec3 viewer_side_origin = surface.point + facing.geometric * origin_offset(surface);

  Vec3 color = material.color * kAmbient;
  color += direct_light(surface, facing.shading, -ray.direction, viewer_side_origin, material);
  if (depth >= settings_.max_depth) return color;

  const SecondaryRays next = spawn_secondary(ray, surface, material);
  if (next.reflects) {
    ++rays_.reflection;
    color += trace(next.reflected, 0.0, depth + 1) * next.reflection_weight;
  }
  if (material.transmittance > 0.0 && !next.refracts) ++rays_.total_internal_reflections;
  if (next.refracts) {
    ++rays_.refraction;
    color += trace(next.refracted, 0.0, depth + 1) * material.transmittance;
  }
  return color;
}

// Sum over lights of (Kd colour max(0, N.L) + Ks max(0, R.V)^Shine) I_light, for the lights a
// shadow ray reaches. No shadow ray is cast toward a light behind the (facing) normal.
Vec3 Tracer::direct_light(const SurfacePoint& surface, const Vec3& normal, const Vec3& to_viewer,
                          const Vec3& shadow_origin, const ShadingMaterial& material) {
  Vec3 sum;
  for (const PointLight& light : world_.lights) {
    const Vec3 to_light = normalize(light.position - surface.point);
    const double n_dot_l = dot(normal, to_light);
    if (!(n_dot_l > 0.0)) continue;

    const Vec3 shadow_span = light.position - shadow_origin;
    const double light_distance = length(shadow_span);
    const Ray shadow{shadow_origin, shadow_span / light_distance};
    ++rays_.shadow;
    if (is_occluded(world_, settings_.accel, shadow, light_distance, tests_)) continue;

    Vec3 response = material.color * (material.kd * n_dot_l);
    if (material.ks != 0.0) {
      const double r_dot_v = dot(reflect(-to_light, normal), to_viewer);
      if (r_dot_v > 0.0) {
        const double highlight = material.ks * std::pow(r_dot_v, material.shine);
        response += Vec3{highlight, highlight, highlight};
      }
    }
    sum += hadamard(response, light.intensity);
  }
  return sum;
}

// Any reflective or transmitting hit spawns a reflection ray; a transmitting one also a
// refraction ray unless totally internally reflected, in which case T joins the reflection
// weight. Origins are offset off the surface along the geometric normal: to the incoming
// side for reflection, through to the other side for refraction.
SecondaryRays spawn_secondary(const Ray& incoming, const SurfacePoint& surface,
                              const ShadingMaterial& material) {
  SecondaryRays out;
  const bool transmits = material.transmittance > 0.0;
  out.reflects = material.ks > 0.0 || transmits;
  if (!out.reflects) return out;

  const Facing facing = face_toward(surface, incoming.direction);
  const double offset = origin_offset(surface);

  out.reflection_weight = material.ks;
  out.reflected = {surface.point + facing.geometric * offset,
                   normalize(reflect(incoming.direction, facing.shading))};
  if (transmits) {
    // Outside every object is air (ior 1).
    const double eta = facing.entering ? 1.0 / material.ior : material.ior;
    Vec3 direction;
    out.refracts = refract(incoming.direction, facing.shading, eta, direction);
    if (out.refracts) {
      out.refracted = {surface.point - facing.geometric * offset, direction};
    } else {
      out.reflection_weight += material.transmittance;
    }
  }
  return out;
}

}  // namespace raygate::render

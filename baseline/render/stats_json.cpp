// Serialising a RunReport.
#include "render/stats_json.h"

namespace raygate::render {

nlohmann::json to_json(const RunReport& r) {
  const RayCounts& rays = r.stats.rays;
  nlohmann::json doc;
  doc["tool"] = "raygate-baseline";
  doc["version"] = r.version;
  doc["source_sha256"] = r.source_sha256;
  doc["scene"] = r.scene;
  doc["width"] = r.width;
  doc["height"] = r.height;
  doc["sampling"] = to_string(r.sampling);
  doc["accel"] = to_string(r.accel);
  doc["max_depth"] = r.max_depth;
  doc["primitives"] = r.primitives;
  doc["degenerate_primitives"] = r.degenerate_primitives;
  doc["lights"] = r.lights;
  doc["rays"] = {
      {"eye", rays.eye},
      {"eye_hits", rays.eye_hits},
      {"shadow", rays.shadow},
      {"reflection", rays.reflection},
      {"refraction", rays.refraction},
      {"total", rays.eye + rays.shadow + rays.reflection + rays.refraction},
  };
  doc["total_internal_reflections"] = rays.total_internal_reflections;
  doc["tests"] = {{"primitive", r.stats.tests.primitive_tests}, {"bbox", r.stats.tests.bbox_tests}};
  doc["parse_seconds"] = r.parse_seconds;
  doc["prepare_seconds"] = r.prepare_seconds;
  doc["render_seconds"] = r.render_seconds;
  doc["cpu_seconds"] = r.cpu_seconds;
  const double rays_total = double(rays.eye + rays.shadow + rays.reflection + rays.refraction);
  doc["rays_per_second"] = r.render_seconds > 0.0 ? rays_total / r.render_seconds : 0.0;
  return doc;
}

}  // namespace raygate::render

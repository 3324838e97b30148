// The pixel loops.
#include "render/render.h"

#include <utility>
#include <vector>

namespace raygate::render {
namespace {

Vec3 trace_at(Tracer& tracer, const Camera& camera, double x, double y) {
  const Ray ray = camera.ray_at(x, y);
  return tracer.trace_eye(ray, camera.t_min(ray));
}

void render_centers(Tracer& tracer, const Camera& camera, Image& image) {
  for (int j = 0; j < camera.height; ++j) {
    for (int i = 0; i < camera.width; ++i) {
      image.set(i, j, trace_at(tracer, camera, i + 0.5, j + 0.5));
    }
  }
}

void trace_corner_row(Tracer& tracer, const Camera& camera, int j, std::vector<Vec3>& row) {
  for (int i = 0; i <= camera.width; ++i) row[i] = trace_at(tracer, camera, i, j);
}

// Each corner is traced once; two rows of corner colours are kept.
void render_corners(Tracer& tracer, const Camera& camera, Image& image) {
  std::vector<Vec3> above(std::size_t(camera.width) + 1);
  std::vector<Vec3> below(std::size_t(camera.width) + 1);
  trace_corner_row(tracer, camera, 0, above);
  for (int j = 0; j < camera.height; ++j) {
    trace_corner_row(tracer, camera, j + 1, below);
    for (int i = 0; i < camera.width; ++i) {
      image.set(i, j, (above[i] + above[i + 1] + below[i] + below[i + 1]) * 0.25);
    }
    std::swap(above, below);
  }
}

}  // namespace

Image render(const World& world, const Camera& camera, const RenderOptions& options,
             RenderStats& stats) {
  Image image(camera.width, camera.height);
  Tracer tracer(world, {options.accel, options.max_depth}, stats.rays, stats.tests);
  if (options.sampling == Sampling::corners) {
    render_corners(tracer, camera, image);
  } else {
    render_centers(tracer, camera, image);
  }
  return image;
}

const char* to_string(Accel accel) { return accel == Accel::bbox ? "bbox" : "none"; }

const char* to_string(Sampling sampling) {
  return sampling == Sampling::corners ? "corners" : "center";
}

}  // namespace raygate::render

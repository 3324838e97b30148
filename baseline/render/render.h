// Rendering a whole image: one eye ray per pixel centre, or the SPD procedure of
// (W+1) x (H+1) corner rays with each pixel the mean of its four corners. Single-threaded.
#pragma once

#include "image/image.h"
#include "render/camera.h"
#include "render/tracer.h"
#include "render/world.h"

namespace raygate::render {

enum class Sampling { center, corners };

struct RenderOptions {
  Accel accel = Accel::none;
  Sampling sampling = Sampling::center;
  int max_depth = 5;
};

struct RenderStats {
  RayCounts rays;
  TestCounters tests;
};

// Adds to `stats` (so callers may accumulate).
Image render(const World& world, const Camera& camera, const RenderOptions& options,
             RenderStats& stats);

const char* to_string(Accel accel);
const char* to_string(Sampling sampling);

}  // namespace raygate::render

// The Monte Carlo estimator: paths from the camera through each pixel, bouncing off diffuse and
// glossy surfaces, with the point lights sampled at every bounce (next-event estimation) and the
// background as a uniform sky seen by paths that escape. Each pixel averages `spp` paths; its
// random numbers come from its own stream keyed by (seed, pixel), so another seed gives
// independent noise around the same expected image.
#pragma once

#include <cstdint>

#include "bvh.h"
#include "image.h"
#include "scene.h"

namespace nff {

struct RenderSettings {
  int samples_per_pixel = 16;
  std::uint64_t seed = 1;
  int max_depth = 6;  // path vertices; Russian roulette may end a path sooner
};

Image render(const Scene& scene, const Bvh& bvh, const RenderSettings& settings);

}  // namespace nff

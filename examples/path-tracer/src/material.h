// How light leaves a surface, from NFF's `f R G B Kd Ks Shine T ior`: a Lambertian lobe of albedo
// Kd * colour plus a glossy lobe of weight Ks, the energy-normalised Phong lobe of exponent
// Shine around the mirror direction (Lafortune and Willems' "modified Phong"). Transmission is
// read and ignored: every surface is opaque and two-sided.
#pragma once

#include "rng.h"
#include "sampling.h"
#include "scene.h"

namespace nff {

// The BRDF times cos(theta_in): what a light seen from `point` along `in` contributes per unit
// of its intensity. `n` faces the viewer, `out` points back to the viewer.
Vec3 reflected(const Material& m, Vec3 n, Vec3 out, Vec3 in);

// The next direction of a path and the factor its throughput is multiplied by (BRDF * cos /
// pdf, divided by the chance of picking the lobe). `valid` is false when the sampled direction
// falls below the surface: the path ends there.
struct Bounce {
  Vec3 direction;
  Vec3 weight;
  bool valid = false;
};

Bounce sample_bounce(const Material& m, Vec3 n, Vec3 out, Rng& rng);

}  // namespace nff

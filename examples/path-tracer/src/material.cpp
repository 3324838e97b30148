#include "material.h"

#include <algorithm>

namespace nff {
namespace {

double luminance(Vec3 c) { return 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z; }

Vec3 albedo(const Material& m) { return m.colour * m.kd; }

double exponent(const Material& m) { return std::max(m.shine, 1.0); }

// The chance a bounce picks the glossy lobe: its share of the reflected energy.
double glossy_chance(const Material& m) {
  const double diffuse = luminance(albedo(m));
  if (m.ks <= 0) return 0;
  return m.ks / (m.ks + diffuse);
}

}  // namespace

Vec3 reflected(const Material& m, Vec3 n, Vec3 out, Vec3 in) {
  const double cos_in = dot(n, in);
  if (cos_in <= 0) return {};
  Vec3 brdf = albedo(m) * (1 / kPi);
  if (m.ks > 0) {
    const double e = exponent(m);
    const double c = dot(mirror(-out, n), in);
    if (c > 0) {
      const double glossy = m.ks * (e + 2) / (2 * kPi) * std::pow(c, e);
      brdf += Vec3{glossy, glossy, glossy};
    }
  }
  return brdf * cos_in;
}

Bounce sample_bounce(const Material& m, Vec3 n, Vec3 out, Rng& rng) {
  const double p_glossy = glossy_chance(m);
  const double pick = rng.uniform();
  const double u1 = rng.uniform();
  const double u2 = rng.uniform();
  Bounce bounce;
  if (pick < p_glossy) {
    const double e = exponent(m);
    bounce.direction = sample_phong_lobe(mirror(-out, n), e, u1, u2);
    const double cos_in = dot(n, bounce.direction);
    if (cos_in <= 0) return bounce;
    // brdf * cos / pdf: the lobe's cos^e cancels against the pdf's.
    const double w = m.ks * (e + 2) / (e + 1) * cos_in / p_glossy;
    bounce.weight = {w, w, w};
  } else {
    bounce.direction = sample_cosine(n, u1, u2);
    if (dot(n, bounce.direction) <= 0) return bounce;
    bounce.weight = albedo(m) * (1 / (1 - p_glossy));  // cos / pi cancels against the pdf
  }
  bounce.valid = true;
  return bounce;
}

}  // namespace nff

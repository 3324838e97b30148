#include "render.h"

#include <algorithm>
#include <cmath>

#include "material.h"
#include "rng.h"
#include "sampling.h"

namespace nff {
namespace {

constexpr double kEpsilon = 1e-6;  // secondary rays start this far along, off the surface
constexpr int kRouletteAfter = 3;  // bounces before Russian roulette may end a path

// NFF lights have no falloff and no unit; as in the classic Lambert reading of NFF
// (examples/nff-tracer), a light of colour C lights a white Lambertian surface facing it to
// C / sqrt(number of lights). With a BRDF of albedo / pi that is an intensity of pi * C / sqrt(n).
Vec3 light_intensity(const Scene& scene, const Light& light) {
  return light.colour * (kPi / std::sqrt(static_cast<double>(scene.lights.size())));
}

class PathTracer {
 public:
  PathTracer(const Scene& scene, const Bvh& bvh, int max_depth)
      : scene_(scene), bvh_(bvh), max_depth_(max_depth) {}

  Vec3 radiance(Ray ray, double t_min, Rng& rng) const {
    Vec3 sum;
    Vec3 throughput{1, 1, 1};
    for (int depth = 0; depth < max_depth_; ++depth) {
      Hit hit;
      if (!bvh_.closest(ray, t_min, hit)) return sum + throughput * scene_.background;
      const Material& m = scene_.materials[hit.material];
      const Vec3 point = ray.at(hit.t);
      const Vec3 out = -ray.direction;
      // Every shape is two-sided: the normal faces where the ray came from.
      const Vec3 n = dot(hit.normal, out) < 0 ? -hit.normal : hit.normal;
      sum += throughput * direct_light(m, point, n, out);
      const Bounce bounce = sample_bounce(m, n, out, rng);
      if (!bounce.valid) break;
      throughput = throughput * bounce.weight;
      if (depth + 1 >= kRouletteAfter && !survives(throughput, rng)) break;
      ray = {point, bounce.direction};
      t_min = kEpsilon;
    }
    return sum;
  }

 private:
  Vec3 direct_light(const Material& m, Vec3 point, Vec3 n, Vec3 out) const {
    Vec3 sum;
    for (const Light& light : scene_.lights) {
      const Vec3 to_light = light.position - point;
      const double distance = length(to_light);
      const Vec3 in = to_light * (1 / distance);
      if (dot(n, in) <= 0) continue;  // behind the surface: no shadow ray needed
      if (bvh_.occluded({point, in}, kEpsilon, distance)) continue;
      sum += reflected(m, n, out, in) * light_intensity(scene_, light);
    }
    return sum;
  }

  // Russian roulette: a dim path goes on with probability q and is then weighted 1 / q, which
  // keeps the estimate unbiased while most dim paths stop.
  static bool survives(Vec3& throughput, Rng& rng) {
    const double q = std::min(0.95, std::max({throughput.x, throughput.y, throughput.z}));
    if (!(q > 0) || rng.uniform() >= q) return false;
    throughput = throughput * (1 / q);
    return true;
  }

  const Scene& scene_;
  const Bvh& bvh_;
  int max_depth_;
};

// The pinhole camera of NFF's view: `angle` spans the image width.
struct Camera {
  Vec3 from, forward, right, up;
  double half_width, aspect, hither;
  int width, height;

  explicit Camera(const View& view)
      : from(view.from),
        forward(normalize(view.at - view.from)),
        half_width(std::tan(view.angle_degrees * kPi / 360)),
        aspect(static_cast<double>(view.height) / view.width),
        hither(view.hither),
        width(view.width),
        height(view.height) {
    up = normalize(view.up - forward * dot(view.up, forward));
    right = normalize(cross(forward, up));
  }

  // The ray through image position (x, y) in pixels, (0, 0) the top left corner.
  Ray ray(double x, double y) const {
    const double u = (2 * x / width - 1) * half_width;
    const double v = (1 - 2 * y / height) * half_width * aspect;
    return {from, normalize(forward + right * u + up * v)};
  }
};

}  // namespace

Image render(const Scene& scene, const Bvh& bvh, const RenderSettings& settings) {
  const Camera camera(scene.view);
  const PathTracer tracer(scene, bvh, settings.max_depth);
  Image image{camera.width, camera.height, {}};
  image.rgb.reserve(static_cast<std::size_t>(camera.width) * camera.height * 3);
  const double per_sample = 1.0 / settings.samples_per_pixel;
  for (int y = 0; y < camera.height; ++y) {
    for (int x = 0; x < camera.width; ++x) {
      Rng rng(settings.seed, static_cast<std::uint64_t>(y) * camera.width + x);
      Vec3 sum;
      for (int s = 0; s < settings.samples_per_pixel; ++s) {
        const double jitter_x = rng.uniform();  // a uniform point in the pixel: box filter
        const double jitter_y = rng.uniform();
        const Ray ray = camera.ray(x + jitter_x, y + jitter_y);
        const double hither = camera.hither / dot(ray.direction, camera.forward);
        sum += tracer.radiance(ray, std::max(hither, 0.0), rng);
      }
      const Vec3 mean = sum * per_sample;
      image.rgb.insert(image.rgb.end(), {static_cast<float>(mean.x), static_cast<float>(mean.y),
                                         static_cast<float>(mean.z)});
    }
  }
  return image;
}

}  // namespace nff

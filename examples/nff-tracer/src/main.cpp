// nff-tracer: a small single-threaded Whitted-style ray tracer for NFF scenes, the example
// tracer of raygate's CI templates (see ../README.md).
//
//   usage: tracer SCENE.nff -o IMAGE.png|IMAGE.ppm [--depth N]
//
// Shading follows NFF's usual reading: ambient 0.1 * colour, Lambert and Phong terms per point
// light (intensity 1/sqrt(number of lights)), hard shadows, and mirror reflection weighted by
// Ks up to N bounces (default 5). Transmission is not rendered. Exit 0 ok, 1 the image could not
// be written, 2 bad arguments or a bad scene.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "bvh.h"
#include "image.h"
#include "scene.h"

namespace nff {
namespace {

constexpr double kAmbient = 0.1;
constexpr double kEpsilon = 1e-6;  // secondary rays start this far off the surface

struct Tracer {
  const Scene& scene;
  const Bvh& bvh;
  int max_depth;

  Vec3 direct_light(const Material& m, Vec3 point, Vec3 normal, Vec3 view) const {
    Vec3 sum;
    const double intensity = 1 / std::sqrt(static_cast<double>(scene.lights.size()));
    for (const Light& light : scene.lights) {
      const Vec3 to_light = light.position - point;
      const double distance = length(to_light);
      const Vec3 l = to_light * (1 / distance);
      const double lambert = dot(normal, l);
      if (lambert <= 0) continue;  // the light is behind the surface: no shadow ray needed
      if (bvh.occluded({point, l}, kEpsilon, distance)) continue;
      Vec3 term = m.colour * (m.kd * lambert);
      const double highlight = dot(normal * (2 * lambert) - l, view);
      if (m.ks > 0 && highlight > 0) {
        const double p = std::pow(highlight, std::max(m.shine, 1.0)) * m.ks;
        term += Vec3{p, p, p};
      }
      sum += term * light.colour * intensity;
    }
    return sum;
  }

  Vec3 trace(const Ray& ray, double t_min, int depth) const {
    Hit hit;
    if (!bvh.closest(ray, t_min, hit)) return scene.background;
    const Material& m = scene.materials[hit.material];
    const Vec3 point = ray.at(hit.t);
    // Every shape is two-sided: the normal faces the incoming ray.
    const Vec3 normal = dot(hit.normal, ray.direction) > 0 ? -hit.normal : hit.normal;
    Vec3 colour = m.colour * kAmbient + direct_light(m, point, normal, -ray.direction);
    if (m.ks > 0 && depth < max_depth) {
      const Vec3 mirrored = ray.direction - normal * (2 * dot(ray.direction, normal));
      colour += trace({point, mirrored}, kEpsilon, depth + 1) * m.ks;
    }
    return colour;
  }
};

unsigned char to_byte(double v) {
  if (!(v > 0)) return 0;  // also NaN
  return static_cast<unsigned char>(std::lround(std::min(v, 1.0) * 255));
}

// One eye ray through each pixel's centre; `angle` spans the image's width.
Image render(const Scene& scene, const Bvh& bvh, int max_depth) {
  const View& view = scene.view;
  const Vec3 forward = normalize(view.at - view.from);
  const Vec3 up = normalize(view.up - forward * dot(view.up, forward));
  const Vec3 right = normalize(cross(forward, up));
  const double half = std::tan(view.angle_degrees * M_PI / 360);
  const double aspect = static_cast<double>(view.height) / view.width;
  const Tracer tracer{scene, bvh, max_depth};
  Image image{view.width, view.height, {}};
  image.rgb.reserve(static_cast<std::size_t>(view.width) * view.height * 3);
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) {
      const double u = (2 * (x + 0.5) / view.width - 1) * half;
      const double v = (1 - 2 * (y + 0.5) / view.height) * half * aspect;
      const Vec3 direction = normalize(forward + right * u + up * v);
      const double hither = view.hither / dot(direction, forward);
      const Vec3 c = tracer.trace({view.from, direction}, std::max(hither, 0.0), 1);
      image.rgb.insert(image.rgb.end(), {to_byte(c.x), to_byte(c.y), to_byte(c.z)});
    }
  }
  return image;
}

struct Options {
  std::string scene, image;
  int max_depth = 5;
};

Options parse_arguments(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-o" && i + 1 < argc) options.image = argv[++i];
    else if (arg == "--depth" && i + 1 < argc) options.max_depth = std::atoi(argv[++i]);
    else if (!arg.empty() && arg[0] != '-' && options.scene.empty()) options.scene = arg;
    else throw std::invalid_argument("unexpected argument '" + arg + "'");
  }
  if (options.scene.empty() || options.image.empty())
    throw std::invalid_argument("missing SCENE or -o IMAGE");
  if (options.max_depth < 1 || options.max_depth > 64)
    throw std::invalid_argument("--depth must be 1..64");
  return options;
}

}  // namespace
}  // namespace nff

int main(int argc, char** argv) {
  nff::Options options;
  nff::Scene scene;
  try {
    options = nff::parse_arguments(argc, argv);
    scene = nff::read_nff(options.scene);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "tracer: %s\nusage: tracer SCENE.nff -o IMAGE.png|IMAGE.ppm [--depth N]\n",
                 e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tracer: %s\n", e.what());
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  const nff::Bvh bvh(scene);
  const nff::Image image = nff::render(scene, bvh, options.max_depth);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  try {
    nff::write_image(options.image, image);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tracer: %s\n", e.what());
    return 1;
  }
  std::printf(
      "tracer: %dx%d, %zu spheres, %zu cones, %zu polygons, %zu triangles, %zu BVH nodes, %.6f s\n",
      image.width, image.height, scene.spheres.size(), scene.cones.size(), scene.polygons.size(),
      scene.triangles.size(), bvh.node_count(), seconds.count());
  return 0;
}

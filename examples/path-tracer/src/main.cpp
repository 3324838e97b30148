// path-tracer: a small single-threaded Monte Carlo path tracer for NFF scenes, the example of a
// noisy renderer for raygate's Monte Carlo image check (see ../README.md).
//
//   usage: tracer SCENE.nff -o IMAGE.pfm|IMAGE.png|IMAGE.ppm [--spp N] [--seed S] [--depth N]
//
// Exit 0 ok, 1 the image could not be written, 2 bad arguments or a bad scene.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "bvh.h"
#include "image.h"
#include "render.h"
#include "scene.h"

namespace nff {
namespace {

// The samples per pixel when --spp is not given. raygate's adapter leaves it to the tracer, so
// a commit that changes it is a change raygate judges.
constexpr int kDefaultSamplesPerPixel = 16;

struct Options {
  std::string scene, image;
  RenderSettings settings{kDefaultSamplesPerPixel, 1, 6};
};

// A whole number in [low, high], or invalid_argument naming the option.
long long parse_number(const std::string& option, const char* text, long long low, long long high) {
  char* end = nullptr;
  const long long value = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || value < low || value > high) {
    throw std::invalid_argument(option + " must be a whole number in [" + std::to_string(low) +
                                ", " + std::to_string(high) + "], found '" + text + "'");
  }
  return value;
}

Options parse_arguments(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "-o" && has_value) options.image = argv[++i];
    else if (arg == "--spp" && has_value) {
      options.settings.samples_per_pixel =
          static_cast<int>(parse_number(arg, argv[++i], 1, 1 << 20));
    } else if (arg == "--seed" && has_value) {
      options.settings.seed =
          static_cast<std::uint64_t>(parse_number(arg, argv[++i], 0, (1ll << 62)));
    } else if (arg == "--depth" && has_value) {
      options.settings.max_depth = static_cast<int>(parse_number(arg, argv[++i], 1, 64));
    } else if (!arg.empty() && arg[0] != '-' && options.scene.empty()) {
      options.scene = arg;
    } else {
      throw std::invalid_argument("unexpected argument '" + arg + "'");
    }
  }
  if (options.scene.empty() || options.image.empty())
    throw std::invalid_argument("missing SCENE or -o IMAGE");
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
    std::fprintf(stderr,
                 "tracer: %s\nusage: tracer SCENE.nff -o IMAGE.pfm|IMAGE.png|IMAGE.ppm [--spp N] "
                 "[--seed S] [--depth N]\n",
                 e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tracer: %s\n", e.what());
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  const nff::Bvh bvh(scene);
  const nff::Image image = nff::render(scene, bvh, options.settings);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  try {
    nff::write_image(options.image, image);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tracer: %s\n", e.what());
    return 1;
  }
  std::printf(
      "tracer: %dx%d, %d spp, seed %llu, %zu shapes, %zu BVH nodes, %.3f s\n", image.width,
      image.height, options.settings.samples_per_pixel,
      static_cast<unsigned long long>(options.settings.seed),
      scene.spheres.size() + scene.cones.size() + scene.polygons.size() + scene.triangles.size(),
      bvh.node_count(), seconds.count());
  return 0;
}

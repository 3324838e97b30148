#include <array>
#include <stdexcept>
#include <string>

#include "generators/generators.h"
#include "spd.h"

namespace raygate::scenes {
namespace {

// name, description, SPD default size, whether the size factor matters, generator.
constexpr std::array<SceneGenerator, 13> kGenerators{{
    {"balls", "sphereflake: fractal of 9-child spheres on a floor, 3 lights", 4, true,
     generate_balls},
    {"gears", "block of meshing 36-tooth gears, concave 144-gons, some transparent", 4, true,
     generate_gears},
    {"mount", "fractal mountain of triangles with 4 glass spheres, 1 light", 6, true,
     generate_mount},
    {"rings", "pyramid of dodecahedral ring objects (cylinders and spheres), 3 lights", 7, true,
     generate_rings},
    {"teapot", "Newell teapot as smooth triangles on a checkerboard, 2 lights", 6, true,
     generate_teapot},
    {"tetra", "Sierpinski tetrahedron of triangles, mostly background, 1 light", 6, true,
     generate_tetra},
    {"tree", "binary branching tree of cones and spheres on a field, 7 lights", 11, true,
     generate_tree},
    {"lattice", "cubic lattice of shiny spheres joined by matte cylinders, 6 lights", 12, true,
     generate_lattice},
    {"shells", "Pickover's sea shell: a spiral of overlapping spheres, 1 light", 5, true,
     generate_shells},
    {"jacks", "recursive jacks of cylinders and spheres (transform stack), 1 light", 1, true,
     generate_jacks},
    {"sombrero", "damped-cosine height field as triangles, 1 light", 1, true, generate_sombrero},
    {"sample", "three tessellated tori, a cone and a disc (size ignored)", 1, false,
     generate_sample},
    {"nurbtst", "one tessellated NURBS patch (size ignored)", 1, false, generate_nurbtst},
}};

}  // namespace

std::span<const SceneGenerator> all_generators() { return kGenerators; }

const SceneGenerator* find_generator(std::string_view name) {
  for (const SceneGenerator& g : kGenerators) {
    if (g.name == name) return &g;
  }
  return nullptr;
}

int max_size(const SceneGenerator& generator) {
  // Each limit keeps a scene below roughly a million primitives (spd-spec.md §3 counts);
  // mount stops at 7 because its hash is undefined behaviour in C above that (§8).
  const std::string_view n = generator.name;
  if (n == "balls") return 6;
  if (n == "gears") return 12;
  if (n == "mount") return 7;
  if (n == "rings") return 20;
  if (n == "teapot") return 64;
  if (n == "tetra") return 10;
  if (n == "tree") return 18;
  if (n == "lattice") return 40;
  if (n == "shells") return 12;
  if (n == "jacks") return 6;
  if (n == "sombrero") return 5;
  return 1000;  // sample and nurbtst ignore the size
}

void generate(std::string_view name, const GenerateOptions& options, std::ostream& out) {
  const SceneGenerator* generator = find_generator(name);
  if (generator == nullptr) {
    throw std::invalid_argument("unknown scene '" + std::string(name) +
                                "' (raygate scenes list shows the 13 SPD scenes)");
  }
  const int size = options.size.value_or(generator->default_size);
  const int limit = max_size(*generator);
  if (size < 1 || size > limit) {
    throw std::invalid_argument("scene '" + std::string(name) + "': size " + std::to_string(size) +
                                " is out of range 1.." + std::to_string(limit));
  }
  if (options.tessellation_resolution < 1 || options.tessellation_resolution > 64) {
    throw std::invalid_argument("tessellation resolution " +
                                std::to_string(options.tessellation_resolution) +
                                " is out of range 1..64");
  }
  if (options.width < 0 || options.width > 16384 || options.height < 0 || options.height > 16384) {
    throw std::invalid_argument("resolution " + std::to_string(options.width) + "x" +
                                std::to_string(options.height) + " is out of range 1..16384");
  }
  NffWriter writer(out, options.mode, options.tessellation_resolution);
  writer.override_resolution(options.width, options.height);
  generator->generate(size, writer);
}

}  // namespace raygate::scenes

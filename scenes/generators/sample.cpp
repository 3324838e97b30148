// sample (spd-spec.md §3.12): the SPD's demo scene, three interlocking tori, a cone and a disc.
// NFF has no torus or disc, so those are always tessellated: the tori as `pp` triangles at the
// writer's resolution, the disc at resolution (4, 1) as quads that collapse to triangles at
// the centre. The size factor is ignored.
#include <array>

#include "generators/generators.h"
#include "lib/tessellate.h"

namespace raygate::scenes {
namespace {

constexpr double kMajorRadius = 2.0;
constexpr double kMinorRadius = 0.5;
constexpr int kDiscResolution = 4;  // the SPD's (4, 1): 16 angular steps, one ring

// Every object shares these coefficients; only the colour changes (§3.12).
SpdMaterial material(const Vec3& color) { return {color, 0.1, 0.7, 0.0, 0.7, 10.0, 0.0, 1.0}; }

struct Torus {
  Vec3 center;
  Vec3 normal;  // not unit length as given; normalised before use
  Vec3 color;
};

// The colours are (1,1,0) then (1,0,1); the SPD's labels "magenta" and "yellow" are swapped.
const std::array<Torus, 3> kTori{{
    {{-1.0, 0.0, 0.0}, {1.0, 1.0, -0.5}, {0.0, 1.0, 1.0}},
    {{0.0, 0.0, 0.0}, {0.0, 1.0, -0.5}, {1.0, 1.0, 0.0}},
    {{1.0, 0.0, 0.0}, {-1.0, 1.0, -0.5}, {1.0, 0.0, 1.0}},
}};

void write_header(NffWriter& out) {
  out.background({0.8, 0.8, 0.8});
  out.view({0.0, 5.0, -5.0}, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, 45.0, 0.001, 512, 512);
  out.light({-10.0, 20.0, -20.0});
}

}  // namespace

void generate_sample(int /*size: ignored*/, NffWriter& out) {
  write_header(out);
  const int res = out.tessellation_resolution();
  for (const Torus& t : kTori) {
    out.material(material(t.color));
    for (const PatchTriangle& tri :
         tessellate_torus(t.center, normalize(t.normal), kMajorRadius, kMinorRadius, res, res)) {
      out.patch(tri.vertices, tri.normals);
    }
  }
  const Vec3 red{1.0, 0.0, 0.0};
  out.material(material(red));
  out.cone({0.0, -2.0, 0.0}, 2.0, {0.0, 2.0, 0.0}, 0.1);
  out.material(material(red));
  for (const Quad& q :
       tessellate_disc({0.0, -2.0, 0.0}, {0.0, 1.0, 0.0}, 0.0, 4.0, kDiscResolution)) {
    out.polygon(q);
  }
}

}  // namespace raygate::scenes

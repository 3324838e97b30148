// The in-memory form of an NFF scene (spd-spec.md §1): what the reader produces and what the
// baseline tracer, the harness and the scene writers consume. Plain values, no behaviour.
#pragma once

#include <string>
#include <vector>

#include "geom/vec3.h"

namespace raygate::nff {

// Where something came from in an NFF file, for error messages and for tools that point back
// at the source ("path:line:column").
struct FileLoc {
  std::string path;
  int line = 0;    // 1-based
  int column = 0;  // 1-based, in bytes
};

// The largest side of an image the reader takes (resolution): 16384, as the harness's suites
// (runner/suite.cpp). One number for the reader, the camera and docs/baseline.md.
inline constexpr int kMaxResolutionSide = 16384;

struct View {
  Vec3 from;
  Vec3 at;
  Vec3 up;
  double angle_degrees = 45.0;  // full field of view, left edge to right edge
  double hither = 0.0;          // lower bound on eye-ray distance
  int width = 512;
  int height = 512;
};

struct Light {
  Vec3 position;
  Vec3 color{1.0, 1.0, 1.0};  // NFF allows an optional RGB; the SPD never writes one
  bool has_color = false;
};

// An `f` line: "f R G B Kd Ks Shine T ior".
struct Material {
  Vec3 color;
  double kd = 0.0;             // diffuse weight
  double ks = 0.0;             // mirror reflection weight, also the Phong highlight weight
  double shine = 0.0;          // Phong exponent
  double transmittance = 0.0;  // weight of the refracted ray
  double ior = 1.0;            // index of refraction, meaningful when transmittance > 0
  FileLoc loc;
};

// Every primitive refers to the material in force when it was read (index into
// Scene::materials). Reading an object before any `f` is an error.
struct Sphere {
  Vec3 center;
  double radius = 0.0;  // negative: inside-visible (kept as written)
  int material = 0;
  FileLoc loc;
};

// Open (cap-less) truncated cone; equal radii make a cylinder.
struct Cone {
  Vec3 base;
  double base_radius = 0.0;
  Vec3 apex;
  double apex_radius = 0.0;
  int material = 0;
  FileLoc loc;
};

// `p N`: a planar polygon, possibly concave, counter-clockwise seen from the front.
struct Polygon {
  std::vector<Vec3> vertices;
  int material = 0;
  FileLoc loc;
};

// `pp N`: a polygon with a normal per vertex, shaded smoothly.
struct Patch {
  std::vector<Vec3> vertices;
  std::vector<Vec3> normals;  // same size as vertices
  int material = 0;
  FileLoc loc;
};

struct Scene {
  std::string path;
  Vec3 background;  // black unless a `b` says otherwise
  View view;
  std::vector<Light> lights;
  std::vector<Material> materials;
  std::vector<Sphere> spheres;
  std::vector<Cone> cones;
  std::vector<Polygon> polygons;
  std::vector<Patch> patches;

  std::size_t primitive_count() const {
    return spheres.size() + cones.size() + polygons.size() + patches.size();
  }
};

}  // namespace raygate::nff

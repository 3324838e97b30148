// The scene as read from an NFF file (Eric Haines' Neutral File Format, the SPD's format):
// the view, the background, point lights, materials and four kinds of shapes.
#pragma once

#include <string>
#include <vector>

#include "vec.h"

namespace nff {

// `f R G B Kd Ks Shine T ior`. Transmission (T, ior) is read but not rendered by this tracer.
struct Material {
  Vec3 colour{1, 1, 1};
  double kd = 1, ks = 0, shine = 1, transmittance = 0, ior = 1;
};

struct Sphere {
  Vec3 centre;
  double radius = 0;
  int material = 0;
};

// `c`: an open truncated cone (a cylinder when both radii are equal), no end caps.
struct Cone {
  Vec3 base, apex;
  double base_radius = 0, apex_radius = 0;
  int material = 0;
};

// `p N`: a flat polygon, possibly concave; tested by the even-odd rule, never triangulated.
struct Polygon {
  std::vector<Vec3> vertices;
  Vec3 normal;  // Newell's normal, unit length
  int material = 0;
};

// `pp N` patches become triangles with a normal per vertex (smooth shading).
struct Triangle {
  Vec3 a, b, c;
  Vec3 normal_a, normal_b, normal_c;
  int material = 0;
};

struct Light {
  Vec3 position;
  Vec3 colour{1, 1, 1};
};

struct View {
  Vec3 from, at{0, 0, -1}, up{0, 1, 0};
  double angle_degrees = 45;  // full horizontal field of view
  double hither = 0;          // eye rays ignore hits nearer than this along the view direction
  int width = 256, height = 256;
};

struct Scene {
  View view;
  Vec3 background;
  std::vector<Light> lights;
  std::vector<Material> materials;
  std::vector<Sphere> spheres;
  std::vector<Cone> cones;
  std::vector<Polygon> polygons;
  std::vector<Triangle> triangles;
};

// Reads an NFF file. Throws std::runtime_error("FILE:LINE: what is wrong") on bad input.
Scene read_nff(const std::string& path);

}  // namespace nff

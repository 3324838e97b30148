// Test helper: the figures spd-spec.md Tables A-D give per generated file (counts, bytes,
// bounding box, view lines, distinct `f` lines), computed from NFF text by a token scan that is
// independent of the reader under test.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "geom/vec3.h"

namespace raygate::test {

struct NffSummary {
  long lines = 0;
  long bytes = 0;
  long spheres = 0;
  long cylinders = 0;  // `c` with equal radii
  long cones = 0;      // `c` with different radii
  long polygons = 0;
  std::map<int, long> polygons_by_vertex_count;
  long patches = 0;
  long lights = 0;
  long f_lines = 0;
  std::set<std::string> distinct_f;     // the `f` lines exactly as written
  std::vector<std::string> view_lines;  // the 6 lines after `v`, exactly as written
  std::string background_line;          // the `b` line, or empty
  Vec3 bbox_min{1e300, 1e300, 1e300};
  Vec3 bbox_max{-1e300, -1e300, -1e300};
};

// Summarises SPD-style NFF (one entity per line, `c` on one line). Throws std::runtime_error on
// anything it does not understand.
NffSummary summarize_nff(const std::string& text);

// "%g" of each component, space separated: how Table B prints a corner.
std::string format_corner(const Vec3& v);

}  // namespace raygate::test

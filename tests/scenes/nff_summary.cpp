#include "nff_summary.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "lib/nff_writer.h"

namespace raygate::test {
namespace {

void grow(NffSummary& s, const Vec3& lo, const Vec3& hi) {
  s.bbox_min = {std::min(s.bbox_min.x, lo.x), std::min(s.bbox_min.y, lo.y),
                std::min(s.bbox_min.z, lo.z)};
  s.bbox_max = {std::max(s.bbox_max.x, hi.x), std::max(s.bbox_max.y, hi.y),
                std::max(s.bbox_max.z, hi.z)};
}

// The AABB of a circle of radius r around `center`, in the plane normal to unit axis d.
void grow_rim(NffSummary& s, const Vec3& center, double r, const Vec3& d) {
  const Vec3 e{r * std::sqrt(std::max(0.0, 1.0 - d.x * d.x)),
               r * std::sqrt(std::max(0.0, 1.0 - d.y * d.y)),
               r * std::sqrt(std::max(0.0, 1.0 - d.z * d.z))};
  grow(s, center - e, center + e);
}

Vec3 read_vec(std::istringstream& in) {
  Vec3 v;
  if (!(in >> v.x >> v.y >> v.z)) throw std::runtime_error("nff_summary: expected 3 numbers");
  return v;
}

}  // namespace

NffSummary summarize_nff(const std::string& text) {
  NffSummary s;
  s.bytes = static_cast<long>(text.size());
  std::vector<std::string> lines;
  {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) lines.push_back(line);
  }
  s.lines = static_cast<long>(lines.size());
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::istringstream in(lines[i]);
    std::string key;
    in >> key;
    if (key == "b") {
      s.background_line = lines[i];
    } else if (key == "v") {
      for (int k = 1; k <= 6; ++k) s.view_lines.push_back(lines.at(i + k));
      i += 6;
    } else if (key == "l") {
      ++s.lights;
    } else if (key == "f") {
      ++s.f_lines;
      s.distinct_f.insert(lines[i]);
    } else if (key == "s") {
      ++s.spheres;
      const Vec3 c = read_vec(in);
      double r = 0;
      in >> r;
      const Vec3 e{std::abs(r), std::abs(r), std::abs(r)};
      grow(s, c - e, c + e);
    } else if (key == "c") {
      const Vec3 base = read_vec(in);
      double rb = 0;
      in >> rb;
      const Vec3 apex = read_vec(in);
      double ra = 0;
      in >> ra;
      (rb == ra ? s.cylinders : s.cones) += 1;
      const Vec3 d = normalize(apex - base);
      grow_rim(s, base, std::abs(rb), d);
      grow_rim(s, apex, std::abs(ra), d);
    } else if (key == "p" || key == "pp") {
      int n = 0;
      in >> n;
      if (key == "p") {
        ++s.polygons;
        ++s.polygons_by_vertex_count[n];
      } else {
        ++s.patches;
      }
      for (int k = 1; k <= n; ++k) {
        std::istringstream vin(lines.at(i + static_cast<std::size_t>(k)));
        const Vec3 v = read_vec(vin);
        grow(s, v, v);
      }
      i += static_cast<std::size_t>(n);
    } else if (!key.empty() && key[0] == '#') {
      continue;
    } else {
      throw std::runtime_error("nff_summary: unexpected line: " + lines[i]);
    }
  }
  return s;
}

std::string format_corner(const Vec3& v) {
  return scenes::format_g(v.x) + " " + scenes::format_g(v.y) + " " + scenes::format_g(v.z);
}

}  // namespace raygate::test

// Shared by the scene writer tests: a small NFF scene with one of every primitive, and helpers
// to write a scene to a string and to read numbers back out of the written text.
#pragma once

#include <cctype>
#include <cstdlib>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "nff/parser.h"
#include "writers/scene_writers.h"

namespace raygate::writers::test {

// Two lights; materials: 1 diffuse+mirror, 2 transmitter, 3 diffuse. A sphere, an open cone, a
// cylinder, a concave U-shaped octagon (area 5, CCW seen from +z) and a smooth patch.
inline constexpr std::string_view kScene = R"(b 0.1 0.2 0.3
v
from 0 -10 0
at 0 0 0
up 0 0 1
angle 40
hither 1
resolution 64 48
l 5 -5 5
l -5 -5 5
f 1 0 0 0.7 0.3 20 0 1
s 1 2 3 0.5
f 0 1 0 0.2 0 100000 0.8 1.5
c 0 0 0 1 0 0 2 0.25
c 1 0 0 0.5 1 0 1 0.5
f 0 0 1 1 0 100000 0 0
p 8
0 0 0
3 0 0
3 2 0
2 2 0
2 1 0
1 1 0
1 2 0
0 2 0
pp 3
0 0 1 0 0 1
1 0 1 0.6 0 0.8
0 1 1 0 0.6 0.8
)";

inline nff::Scene parse(std::string_view text = kScene) {
  return nff::parse_nff(text, "scene.nff");
}

inline std::string pov_text(const nff::Scene& scene) {
  std::ostringstream out;
  write_pov(scene, out);
  return out.str();
}

inline std::string obj_text(const nff::Scene& scene, const WriteOptions& options = {}) {
  std::ostringstream out;
  write_obj(scene, out, "scene.mtl", options);
  return out.str();
}

inline std::string mtl_text(const nff::Scene& scene) {
  std::ostringstream out;
  write_mtl(scene, out);
  return out.str();
}

inline std::string pbrt_text(const nff::Scene& scene, const WriteOptions& options = {}) {
  std::ostringstream out;
  write_pbrt(scene, out, "scene.exr", options);
  return out.str();
}

// The lines of `text` that start with `prefix`.
inline std::vector<std::string> lines_starting(const std::string& text, std::string_view prefix) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) == 0) lines.push_back(line);
  }
  return lines;
}

// Every number in `text`, in order, reading past '<', '>', ',', '[' and the like; digits that
// end a word ("point3", "F1") are not numbers.
inline std::vector<double> numbers_in(std::string_view text) {
  std::vector<double> values;
  std::string s(text);
  const char* p = s.c_str();
  const auto word_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
  };
  while (*p != '\0') {
    char* end = nullptr;
    const bool starts_number = (p == s.c_str() || !word_char(p[-1])) &&
                               ((*p >= '0' && *p <= '9') || *p == '-' || *p == '.');
    const double v = starts_number ? std::strtod(p, &end) : 0.0;
    if (starts_number && end != p) {
      values.push_back(v);
      p = end;
    } else {
      ++p;
    }
  }
  return values;
}

// The numbers on the first line of `text` that starts with `prefix` (after the prefix).
inline std::vector<double> numbers_after(const std::string& text, std::string_view prefix) {
  const std::vector<std::string> lines = lines_starting(text, prefix);
  if (lines.empty()) return {};
  return numbers_in(std::string_view(lines.front()).substr(prefix.size()));
}

inline std::size_t count(const std::string& text, std::string_view what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace raygate::writers::test

// A linear RGB float image as the tracer produces it: no gamma, no clamping (values above 1
// are kept; clamping happens only when writing an 8-bit file).
#pragma once

#include <cstddef>
#include <vector>

#include "geom/vec3.h"

namespace raygate {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgb;  // row-major from the top-left pixel, 3 floats per pixel

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3, 0.0f) {}

  std::size_t offset(int x, int y) const {
    return (std::size_t(y) * std::size_t(width) + std::size_t(x)) * 3;
  }
  void set(int x, int y, const Vec3& c) {
    const std::size_t o = offset(x, y);
    rgb[o] = static_cast<float>(c.x);
    rgb[o + 1] = static_cast<float>(c.y);
    rgb[o + 2] = static_cast<float>(c.z);
  }
  Vec3 at(int x, int y) const {
    const std::size_t o = offset(x, y);
    return {rgb[o], rgb[o + 1], rgb[o + 2]};
  }
};

}  // namespace raygate

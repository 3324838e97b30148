// Writing the rendered image. The film holds linear radiance as floats; the file's extension
// picks the format: .pfm keeps those floats exactly (what raygate's Monte Carlo image check
// wants: averages of noisy renders must not pass through a clamp or a gamma curve first), .png
// and .ppm are 8-bit with a 2.2 gamma for looking at. The PNG is uncompressed (stored deflate
// blocks), so no zlib is needed.
#pragma once

#include <string>
#include <vector>

namespace nff {

struct Image {
  int width = 0, height = 0;
  std::vector<float> rgb;  // width * height * 3 linear values, top row first
};

// Throws std::runtime_error naming the path when it cannot be written.
void write_image(const std::string& path, const Image& image);

}  // namespace nff

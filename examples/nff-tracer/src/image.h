// Writing the rendered image: 8-bit RGB, top row first, as binary PPM (P6) or PNG, chosen by the
// file name's extension. The PNG is uncompressed (stored deflate blocks), so no zlib is needed.
#pragma once

#include <string>
#include <vector>

namespace nff {

struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;  // width * height * 3 bytes
};

// Throws std::runtime_error naming the path when it cannot be written.
void write_image(const std::string& path, const Image& image);

}  // namespace nff

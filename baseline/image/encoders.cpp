// The uncompressed formats: PPM, PFM and TGA, each a short header and the pixels.
#include "image/encoders.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>

namespace raygate {
namespace {

std::string netpbm_header(const char* magic, const Image& image, const char* last_line) {
  return std::string(magic) + "\n" + std::to_string(image.width) + " " +
         std::to_string(image.height) + "\n" + last_line + "\n";
}

void append_le16(std::string& out, int value) {
  out.push_back(static_cast<char>(value & 0xFF));
  out.push_back(static_cast<char>((value >> 8) & 0xFF));
}

// Little-endian whatever the host is: PFM says the byte order in its header, and a fixed one
// keeps the bytes the same on every machine.
void append_le_float(std::string& out, float value) {
  const auto bits = std::bit_cast<std::uint32_t>(value);
  for (int shift = 0; shift < 32; shift += 8)
    out.push_back(static_cast<char>((bits >> shift) & 0xFF));
}

}  // namespace

unsigned char to_8bit(float value) {
  const double clamped = value > 0.0f ? (value < 1.0f ? double(value) : 1.0) : 0.0;
  return static_cast<unsigned char>(std::floor(clamped * 255.0 + 0.5));
}

std::string encode_ppm(const Image& image) {
  std::string out = netpbm_header("P6", image, "255");
  out.reserve(out.size() + image.rgb.size());
  for (const float value : image.rgb) out.push_back(static_cast<char>(to_8bit(value)));
  return out;
}

std::string encode_pfm(const Image& image) {
  std::string out = netpbm_header("PF", image, "-1.0");
  out.reserve(out.size() + image.rgb.size() * 4);
  for (int y = image.height - 1; y >= 0; --y) {
    const std::size_t row = image.offset(0, y);
    for (std::size_t i = 0; i < std::size_t(image.width) * 3; ++i) {
      append_le_float(out, image.rgb[row + i]);
    }
  }
  return out;
}

std::string encode_tga(const Image& image) {
  if (image.width > 0xFFFF || image.height > 0xFFFF) {
    throw std::length_error("TGA holds at most 65535 x 65535 pixels");
  }
  std::string out;
  out.reserve(18 + image.rgb.size());
  out.append({0, 0, 2});  // no id, no colour map, uncompressed true-colour
  out.append(5, '\0');    // colour map specification (unused)
  append_le16(out, 0);    // x origin
  append_le16(out, 0);    // y origin
  append_le16(out, image.width);
  append_le16(out, image.height);
  out.push_back(24);    // bits per pixel
  out.push_back(0x20);  // first row is the top row, no alpha bits
  for (std::size_t i = 0; i < image.rgb.size(); i += 3) {
    out.push_back(static_cast<char>(to_8bit(image.rgb[i + 2])));
    out.push_back(static_cast<char>(to_8bit(image.rgb[i + 1])));
    out.push_back(static_cast<char>(to_8bit(image.rgb[i])));
  }
  return out;
}

}  // namespace raygate

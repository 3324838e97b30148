#include "image.h"

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <stdexcept>

namespace nff {
namespace {

using Bytes = std::vector<unsigned char>;

void put_u32_big_endian(Bytes& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<unsigned char>(value >> shift));
}

// The CRC-32 of PNG chunks (polynomial 0xEDB88320, bit by bit: small images, no table needed).
std::uint32_t crc32(const unsigned char* data, std::size_t size) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) {
    crc ^= data[i];
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return crc ^ 0xFFFFFFFFu;
}

void put_chunk(Bytes& png, const char type[4], const Bytes& data) {
  put_u32_big_endian(png, static_cast<std::uint32_t>(data.size()));
  const std::size_t typed_from = png.size();
  png.insert(png.end(), type, type + 4);
  png.insert(png.end(), data.begin(), data.end());
  put_u32_big_endian(png, crc32(png.data() + typed_from, png.size() - typed_from));
}

// A zlib stream of stored (uncompressed) deflate blocks of at most 65535 bytes each.
Bytes zlib_stored(const Bytes& raw) {
  Bytes out{0x78, 0x01};
  std::uint32_t a = 1, b = 0;  // Adler-32
  for (unsigned char byte : raw) a = (a + byte) % 65521, b = (b + a) % 65521;
  std::size_t at = 0;
  do {
    const std::size_t size = std::min<std::size_t>(65535, raw.size() - at);
    const bool last = at + size == raw.size();
    out.push_back(last ? 1 : 0);
    const auto len = static_cast<std::uint16_t>(size), nlen = static_cast<std::uint16_t>(~len);
    out.insert(out.end(),
               {static_cast<unsigned char>(len & 0xFF), static_cast<unsigned char>(len >> 8),
                static_cast<unsigned char>(nlen & 0xFF), static_cast<unsigned char>(nlen >> 8)});
    out.insert(out.end(), raw.begin() + static_cast<long>(at),
               raw.begin() + static_cast<long>(at + size));
    at += size;
  } while (at < raw.size());
  put_u32_big_endian(out, (b << 16) | a);
  return out;
}

Bytes encode_png(const Image& image) {
  Bytes png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  Bytes header;
  put_u32_big_endian(header, static_cast<std::uint32_t>(image.width));
  put_u32_big_endian(header, static_cast<std::uint32_t>(image.height));
  header.insert(header.end(), {8, 2, 0, 0, 0});  // 8 bits per channel, RGB, no interlace
  put_chunk(png, "IHDR", header);
  Bytes rows;  // every row starts with filter type 0 (none)
  const std::size_t row_bytes = static_cast<std::size_t>(image.width) * 3;
  for (int y = 0; y < image.height; ++y) {
    rows.push_back(0);
    const auto from = image.rgb.begin() + static_cast<long>(y * row_bytes);
    rows.insert(rows.end(), from, from + static_cast<long>(row_bytes));
  }
  put_chunk(png, "IDAT", zlib_stored(rows));
  put_chunk(png, "IEND", {});
  return png;
}

Bytes encode_ppm(const Image& image) {
  const std::string header =
      "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
  Bytes ppm(header.begin(), header.end());
  ppm.insert(ppm.end(), image.rgb.begin(), image.rgb.end());
  return ppm;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

void write_image(const std::string& path, const Image& image) {
  Bytes bytes;
  if (ends_with(path, ".png")) bytes = encode_png(image);
  else if (ends_with(path, ".ppm")) bytes = encode_ppm(image);
  else throw std::runtime_error(path + ": unknown image format (use .png or .ppm)");
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()),
            static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) throw std::runtime_error(path + ": cannot write the image");
}

}  // namespace nff

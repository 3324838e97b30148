// PNG for the 8-bit RGB images the baseline writes: signature, IHDR, one IDAT, IEND (PNG
// specification, ISO/IEC 15948). zlib does the deflate and the CRCs; the row filters are here.
#include <zlib.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "image/encoders.h"

namespace raygate {
namespace {

using Bytes = std::vector<unsigned char>;
constexpr std::size_t kBytesPerPixel = 3;

void append_be32(std::string& out, std::uint32_t value) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out.push_back(static_cast<char>((value >> shift) & 0xFF));
}

// length, type, data, CRC of type and data.
void append_chunk(std::string& out, std::string_view type, std::string_view data) {
  append_be32(out, static_cast<std::uint32_t>(data.size()));
  const std::size_t crc_from = out.size();
  out.append(type);
  out.append(data);
  const auto* covered = reinterpret_cast<const Bytef*>(out.data() + crc_from);
  append_be32(
      out, static_cast<std::uint32_t>(crc32(0, covered, static_cast<uInt>(out.size() - crc_from))));
}

unsigned char paeth(unsigned char a, unsigned char b, unsigned char c) {
  const int p = int(a) + int(b) - int(c);
  const int pa = std::abs(p - int(a));
  const int pb = std::abs(p - int(b));
  const int pc = std::abs(p - int(c));
  if (pa <= pb && pa <= pc) return a;
  return pb <= pc ? b : c;
}

// Row `row` filtered with `type` (0 none, 1 sub, 2 up, 3 average, 4 Paeth) against `above`.
Bytes filter_row(int type, const Bytes& row, const Bytes& above) {
  Bytes out(row.size());
  for (std::size_t i = 0; i < row.size(); ++i) {
    const unsigned char a = i >= kBytesPerPixel ? row[i - kBytesPerPixel] : 0;
    const unsigned char b = above[i];
    const unsigned char c = i >= kBytesPerPixel ? above[i - kBytesPerPixel] : 0;
    unsigned char predicted = 0;
    switch (type) {
      case 1: predicted = a; break;
      case 2: predicted = b; break;
      case 3: predicted = static_cast<unsigned char>((int(a) + int(b)) / 2); break;
      case 4: predicted = paeth(a, b, c); break;
      default: break;
    }
    out[i] = static_cast<unsigned char>(row[i] - predicted);
  }
  return out;
}

// The usual heuristic: residuals read as signed bytes, smallest sum of magnitudes wins; ties go
// to the lower filter type, so the choice is deterministic.
long residual_cost(const Bytes& filtered) {
  long sum = 0;
  for (const unsigned char v : filtered) sum += v < 128 ? v : 256 - v;
  return sum;
}

// Each row as PNG stores it before compression: its filter type byte, then the residuals.
Bytes filtered_scanlines(const Image& image) {
  const std::size_t stride = std::size_t(image.width) * kBytesPerPixel;
  Bytes out;
  out.reserve((stride + 1) * std::size_t(image.height));
  Bytes above(stride, 0);
  Bytes row(stride);
  for (int y = 0; y < image.height; ++y) {
    const std::size_t from = image.offset(0, y);
    for (std::size_t i = 0; i < stride; ++i) row[i] = to_8bit(image.rgb[from + i]);
    int best_type = 0;
    Bytes best = filter_row(0, row, above);
    long best_cost = residual_cost(best);
    for (int type = 1; type <= 4; ++type) {
      Bytes candidate = filter_row(type, row, above);
      const long cost = residual_cost(candidate);
      if (cost < best_cost) {
        best_type = type;
        best = std::move(candidate);
        best_cost = cost;
      }
    }
    out.push_back(static_cast<unsigned char>(best_type));
    out.insert(out.end(), best.begin(), best.end());
    above.swap(row);
  }
  return out;
}

std::string deflate(const Bytes& data) {
  uLongf size = compressBound(static_cast<uLong>(data.size()));
  std::string out(size, '\0');
  const int status = compress2(reinterpret_cast<Bytef*>(out.data()), &size, data.data(),
                               static_cast<uLong>(data.size()), Z_DEFAULT_COMPRESSION);
  if (status != Z_OK) throw std::runtime_error("zlib could not compress the image");
  out.resize(size);
  return out;
}

}  // namespace

std::string encode_png(const Image& image) {
  if (image.width <= 0 || image.height <= 0)
    throw std::length_error("PNG needs at least 1 x 1 pixels");
  std::string out = "\x89PNG\r\n\x1a\n";
  std::string header;
  append_be32(header, static_cast<std::uint32_t>(image.width));
  append_be32(header, static_cast<std::uint32_t>(image.height));
  header.append({8, 2, 0, 0, 0});  // 8 bits, RGB, deflate, adaptive filtering, no interlace
  append_chunk(out, "IHDR", header);
  append_chunk(out, "IDAT", deflate(filtered_scanlines(image)));
  append_chunk(out, "IEND", {});
  return out;
}

}  // namespace raygate

// OpenImageIO output for the baseline's images.
#include "image/image_writer.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>
#include <vector>

namespace raygate {
namespace {

std::string lower_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool is_float_format(const std::string& ext) {
  return ext == "exr" || ext == "hdr" || ext == "tif" || ext == "tiff" || ext == "pfm";
}

// OpenImageIO stamps EXR and TIFF files with the current time unless told a DateTime; a
// fixed one keeps the bytes reproducible. PNG, PPM and TGA get no date at all.
constexpr const char* kFixedDateTime = "1970:01:01 00:00:00";

bool writes_date_by_default(const std::string& ext) {
  return ext == "exr" || ext == "tif" || ext == "tiff";
}

std::vector<unsigned char> quantize(const Image& image) {
  std::vector<unsigned char> bytes(image.rgb.size());
  for (std::size_t i = 0; i < image.rgb.size(); ++i) bytes[i] = to_8bit(image.rgb[i]);
  return bytes;
}

}  // namespace

unsigned char to_8bit(float value) {
  const double clamped = value > 0.0f ? (value < 1.0f ? double(value) : 1.0) : 0.0;
  return static_cast<unsigned char>(std::floor(clamped * 255.0 + 0.5));
}

std::string check_output_format(const std::string& path) {
  if (lower_extension(path).empty()) {
    return "'" + path + "' has no file extension to choose an image format by";
  }
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    OIIO::geterror();  // clear OpenImageIO's pending message
    return "OpenImageIO cannot write the format of '" + path + "' (use .png, .exr, .ppm, .tga)";
  }
  return {};
}

bool write_image(const std::string& path, const Image& image, std::string& error) {
  auto out = OIIO::ImageOutput::create(path);
  if (!out) {
    error = "cannot write '" + path + "': " + OIIO::geterror();
    return false;
  }
  const std::string ext = lower_extension(path);
  const bool as_float = is_float_format(ext);
  const OIIO::TypeDesc type = as_float ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT8;
  OIIO::ImageSpec spec(image.width, image.height, 3, type);
  if (writes_date_by_default(ext)) spec.attribute("DateTime", kFixedDateTime);
  if (!out->open(path, spec)) {
    error = "cannot write '" + path + "': " + out->geterror();
    return false;
  }
  bool ok = false;
  if (as_float) {
    ok = out->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data());
  } else {
    const std::vector<unsigned char> bytes = quantize(image);
    ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
  }
  std::string write_error = ok ? std::string() : out->geterror();
  if (!out->close() && ok) {
    ok = false;
    write_error = out->geterror();
  }
  if (!ok) error = "cannot write '" + path + "': " + write_error;
  return ok;
}

}  // namespace raygate

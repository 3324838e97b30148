// Picks the encoder by extension and writes its bytes.
#include "image/image_writer.h"

#include "image/file_output.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace raygate {
namespace {

using Encoder = std::string (*)(const Image&);

std::string lower_extension(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

Encoder encoder_for(const std::string& ext) {
  if (ext == "png") return encode_png;
  if (ext == "ppm") return encode_ppm;
  if (ext == "pfm") return encode_pfm;
  if (ext == "tga") return encode_tga;
  return nullptr;
}

}  // namespace

std::string check_output_format(const std::string& path) {
  const std::string ext = lower_extension(path);
  if (ext.empty()) return "'" + path + "' has no file extension to choose an image format by";
  if (encoder_for(ext) == nullptr) {
    return "cannot write '" + path + "': raygate-baseline writes .png, .ppm, .tga (8-bit) and " +
           ".pfm (float); for ." + ext + " write .pfm and convert it, e.g. oiiotool x.pfm -o x." +
           ext;
  }
  return {};
}

bool write_image(const std::string& path, const Image& image, std::string& error) {
  const Encoder encode = encoder_for(lower_extension(path));
  if (encode == nullptr) {
    error = check_output_format(path);
    return false;
  }
  std::string bytes;
  try {
    bytes = encode(image);
  } catch (const std::exception& e) {
    error = "cannot write '" + path + "': " + e.what();
    return false;
  }
  return write_file_replacing(path, bytes, error);
}

}  // namespace raygate

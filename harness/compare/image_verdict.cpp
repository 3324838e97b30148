#include "compare/image_verdict.h"

namespace raygate {

std::string_view to_string(ImageVerdict verdict) {
  switch (verdict) {
    case ImageVerdict::missing: return "missing";
    case ImageVerdict::pass: return "pass";
    case ImageVerdict::warn: return "warn";
    case ImageVerdict::error: return "error";
    case ImageVerdict::fail: return "fail";
  }
  return "error";
}

std::optional<ImageVerdict> parse_image_verdict(std::string_view text) {
  for (const ImageVerdict v : {ImageVerdict::missing, ImageVerdict::pass, ImageVerdict::warn,
                               ImageVerdict::error, ImageVerdict::fail}) {
    if (to_string(v) == text) return v;
  }
  return std::nullopt;
}

}  // namespace raygate

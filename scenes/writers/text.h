// Number formatting for the scene writers: like C's "%.10g" in the C locale. The NFF's own
// values (6 significant digits, spd-spec.md §1.5) come out exactly as written; computed ones
// (camera vectors, tessellated vertices) to 10 digits, far below a pixel, without the noise
// digits of a full round-trip. The same value always gives the same text.
#pragma once

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

#include "geom/vec3.h"

namespace raygate::writers {

// A value computed from finite input that no longer is (a sphere at 1e308 of radius 1e308 gave
// vertices of "inf", written with exit 0; a sweep): the file could not be read back.
inline double finite(double value) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument(
        "a value overflows once converted (coordinates or sizes near 1e308?): the file would "
        "hold \"" +
        fmt::format("{}", value) + "\"");
  }
  return value + 0.0;
}

// 0.078 -> "0.078", 100000 -> "100000", 0.1 * 0.2 -> "0.02", 1e-16 -> "1e-16"; -0 -> "0".
inline std::string num(double value) { return fmt::format("{:.10g}", finite(value)); }

// The shortest text that reads back as exactly this double (up to 17 digits), for values
// whose relations must survive the round trip: POV-Ray checks that the camera's vectors are
// perpendicular to about 1e-10, which 10 digits do not always keep.
inline std::string exact(double value) { return fmt::format("{}", finite(value)); }

// The three components joined by `separator` (", " for POV-Ray, " " elsewhere), each written
// by `format` (num or exact).
inline std::string vec(const Vec3& v, std::string_view separator,
                       std::string (*format)(double) = num) {
  std::string text = format(v.x);
  text += separator;
  text += format(v.y);
  text += separator;
  text += format(v.z);
  return text;
}

// The file name of a scene's path (not its directory), for comments in written files.
inline std::string source_name(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace raygate::writers

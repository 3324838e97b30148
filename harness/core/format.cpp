#include "core/format.h"

#include <fmt/core.h>

#include <cmath>

namespace raygate {

std::string percent(double fraction, int decimals) {
  if (!std::isfinite(fraction)) return "n/a";
  return fmt::format("{:.{}f}%", 100.0 * fraction, decimals);
}

std::string signed_percent(double fraction, int decimals) {
  if (!std::isfinite(fraction)) return "n/a";
  return fmt::format("{:+.{}f}%", 100.0 * fraction, decimals);
}

}  // namespace raygate

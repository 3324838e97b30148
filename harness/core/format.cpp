#include "core/format.h"

#include <fmt/core.h>

#include <algorithm>
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

std::string duration_text(double seconds) {
  if (!(seconds < 90.0)) {
    if (seconds < 90.0 * 60.0) return fmt::format("{:.0f} min", seconds / 60.0);
    return fmt::format("{:.1f} h", seconds / 3600.0);
  }
  return fmt::format("{:.0f} s", std::max(seconds, 0.0));
}

std::string count_text(std::size_t count, std::string_view noun, std::string_view plural) {
  if (count == 1) return fmt::format("1 {}", noun);
  if (plural.empty()) return fmt::format("{} {}s", count, noun);
  return fmt::format("{} {}", count, plural);
}

}  // namespace raygate

#include "core/time_text.h"

#include <ctime>

namespace raygate {

namespace {

std::string format_now(const char* format) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  return std::string(text, std::strftime(text, sizeof text, format, &utc));
}

}  // namespace

std::string utc_timestamp() { return format_now("%Y-%m-%dT%H:%M:%SZ"); }
std::string compact_utc_timestamp() { return format_now("%Y%m%d-%H%M%S"); }

}  // namespace raygate

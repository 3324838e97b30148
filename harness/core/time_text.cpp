#include "core/time_text.h"

#include <ctime>
#include <initializer_list>
#include <utility>

namespace raygate {

namespace {

std::string format_now(const char* format) {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  return std::string(text, std::strftime(text, sizeof text, format, &utc));
}

// The number of `width` digits at `at`, or -1 when they are not all digits.
int digits_at(std::string_view text, std::size_t at, std::size_t width) {
  if (at + width > text.size()) return -1;
  int value = 0;
  for (std::size_t i = at; i < at + width; ++i) {
    if (text[i] < '0' || text[i] > '9') return -1;
    value = value * 10 + (text[i] - '0');
  }
  return value;
}

bool separators_at(std::string_view text, std::initializer_list<std::pair<std::size_t, char>> at) {
  for (const auto& [index, c] : at) {
    if (index >= text.size() || text[index] != c) return false;
  }
  return true;
}

int days_in_month(int year, int month) {
  static const int kDays[] = {31, 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return month == 2 && leap ? 29 : kDays[month - 1];
}

// "", "Z", "+02:00", "-0130": what may follow the seconds.
bool is_zone(std::string_view zone) {
  if (zone.empty() || zone == "Z") return true;
  if (zone[0] != '+' && zone[0] != '-') return false;
  const std::size_t minutes = zone.size() == 6 && zone[3] == ':' ? 4 : 3;
  if (zone.size() != minutes + 2) return false;
  const int hours = digits_at(zone, 1, 2);
  const int mins = digits_at(zone, minutes, 2);
  return hours >= 0 && hours <= 23 && mins >= 0 && mins <= 59;
}

}  // namespace

bool is_iso8601_time(std::string_view text) {
  if (!separators_at(text, {{4, '-'}, {7, '-'}, {10, 'T'}, {13, ':'}, {16, ':'}})) return false;
  const int year = digits_at(text, 0, 4), month = digits_at(text, 5, 2),
            day = digits_at(text, 8, 2);
  const int hour = digits_at(text, 11, 2), minute = digits_at(text, 14, 2);
  const int second = digits_at(text, 17, 2);
  if (year < 0 || month < 1 || month > 12 || day < 1 || day > days_in_month(year, month)) {
    return false;
  }
  if (hour < 0 || hour > 23 || minute < 0 || minute > 59 || second < 0 || second > 60) return false;
  std::size_t at = 19;
  if (at < text.size() && text[at] == '.') {
    const std::size_t end = text.find_first_not_of("0123456789", at + 1);
    if (end == at + 1) return false;
    at = end == std::string_view::npos ? text.size() : end;
  }
  return is_zone(text.substr(at));
}

std::string utc_timestamp() { return format_now("%Y-%m-%dT%H:%M:%SZ"); }
std::string compact_utc_timestamp() { return format_now("%Y%m%d-%H%M%S"); }

}  // namespace raygate

#include "core/time_text.h"

#include <ctime>
#include <initializer_list>
#include <optional>
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

// "", "Z", "+02:00", "-0130": what may follow the seconds, as its offset east of UTC in seconds
// (none: local time, read as UTC); nullopt when it is none of these.
std::optional<long> zone_offset_seconds(std::string_view zone) {
  if (zone.empty() || zone == "Z") return 0L;
  if (zone[0] != '+' && zone[0] != '-') return std::nullopt;
  const std::size_t minutes = zone.size() == 6 && zone[3] == ':' ? 4 : 3;
  if (zone.size() != minutes + 2) return std::nullopt;
  const int hours = digits_at(zone, 1, 2);
  const int mins = digits_at(zone, minutes, 2);
  if (hours < 0 || hours > 23 || mins < 0 || mins > 59) return std::nullopt;
  const long offset = 3600L * hours + 60L * mins;
  return zone[0] == '-' ? -offset : offset;
}

// Days from 1970-01-01 to a date of the proleptic Gregorian calendar (the civil-from-days
// arithmetic: years counted from March, so the leap day ends a year).
long days_since_epoch(int year, int month, int day) {
  const long y = month <= 2 ? year - 1 : year;
  const long era = (y >= 0 ? y : y - 399) / 400;
  const long year_of_era = y - era * 400;
  const long day_of_year = (153L * (month > 2 ? month - 3 : month + 9) + 2) / 5 + day - 1;
  const long day_of_era = year_of_era * 365 + year_of_era / 4 - year_of_era / 100 + day_of_year;
  return era * 146097 + day_of_era - 719468;
}

}  // namespace

std::optional<double> iso8601_epoch_seconds(std::string_view text) {
  if (!separators_at(text, {{4, '-'}, {7, '-'}, {10, 'T'}, {13, ':'}, {16, ':'}})) {
    return std::nullopt;
  }
  const int year = digits_at(text, 0, 4), month = digits_at(text, 5, 2),
            day = digits_at(text, 8, 2);
  const int hour = digits_at(text, 11, 2), minute = digits_at(text, 14, 2);
  const int second = digits_at(text, 17, 2);
  if (year < 0 || month < 1 || month > 12 || day < 1 || day > days_in_month(year, month)) {
    return std::nullopt;
  }
  if (hour < 0 || hour > 23 || minute < 0 || minute > 59 || second < 0 || second > 60) {
    return std::nullopt;
  }
  std::size_t at = 19;
  double fraction = 0.0;
  if (at < text.size() && text[at] == '.') {
    const std::size_t end = text.find_first_not_of("0123456789", at + 1);
    if (end == at + 1) return std::nullopt;
    at = end == std::string_view::npos ? text.size() : end;
    double scale = 0.1;
    for (std::size_t i = 20; i < at && scale > 1e-12; ++i, scale /= 10) {
      fraction += (text[i] - '0') * scale;
    }
  }
  const std::optional<long> offset = zone_offset_seconds(text.substr(at));
  if (!offset) return std::nullopt;
  const long seconds =
      days_since_epoch(year, month, day) * 86400L + 3600L * hour + 60L * minute + second;
  return static_cast<double>(seconds - *offset) + fraction;
}

bool is_iso8601_time(std::string_view text) { return iso8601_epoch_seconds(text).has_value(); }

std::string utc_timestamp() { return format_now("%Y-%m-%dT%H:%M:%SZ"); }
std::string compact_utc_timestamp() { return format_now("%Y%m%d-%H%M%S"); }

}  // namespace raygate

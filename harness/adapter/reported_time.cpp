#include "adapter/reported_time.h"

#include <charconv>
#include <cmath>
#include <string_view>

#include "adapter/adapter.h"
#include "adapter/timing_regex.h"

namespace raygate {
namespace {

// The whole capture as a number, or nullopt ("1.5s" or "" are not numbers).
std::optional<double> to_number(std::string_view text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size()) return std::nullopt;
  if (!std::isfinite(value) || value < 0) return std::nullopt;
  return value;
}

// "[[h:]m:]s" (Blender's "00:01.23", "01:02:03.5") as seconds: at most three parts, each a
// number, every part before the seconds a whole one.
std::optional<double> clock_seconds(std::string_view text) {
  double seconds = 0.0;
  int parts = 0;
  for (;;) {
    const std::size_t colon = text.find(':');
    const std::string_view part = text.substr(0, colon);
    const std::optional<double> value = to_number(part);
    if (!value || ++parts > 3) return std::nullopt;
    seconds = seconds * 60.0 + *value;
    if (colon == std::string_view::npos) return seconds;
    if (*value != std::floor(*value)) return std::nullopt;  // "1.5:00"
    text.remove_prefix(colon + 1);
  }
}

std::optional<double> in_seconds(std::string_view text, TimeUnit unit) {
  if (unit == TimeUnit::clock) return clock_seconds(text);
  const std::optional<double> value = to_number(text);
  if (!value) return std::nullopt;
  return unit == TimeUnit::milliseconds ? *value / 1000.0 : *value;
}

}  // namespace

std::optional<std::string> reported_regex_error(const std::string& pattern) {
  try {
    const TimingRegex re(pattern);
    if (re.capture_groups() != 1) {
      return "must have exactly one capture group (the number), found " +
             std::to_string(re.capture_groups()) + "; write other groups as (?:...)";
    }
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return std::nullopt;
}

constexpr std::size_t kMaxLineSearched = 4096;

std::optional<double> parse_reported_seconds(const Adapter& adapter, std::string_view output) {
  if (adapter.timing.source != TimingSource::reported) return std::nullopt;
  const TimingRegex re(adapter.timing.regex);
  // Line by line from the end: the last report wins, and the matcher never sees a
  // multi-megabyte log as one subject.
  std::size_t end = output.size();  // one past the current line
  for (;;) {
    const std::size_t newline = end == 0 ? std::string_view::npos : output.rfind('\n', end - 1);
    const std::size_t begin = newline == std::string_view::npos ? 0 : newline + 1;
    std::string_view line = output.substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    // A line without an end (a progress bar redrawn with \r) can be megabytes: its end holds
    // the report, and a search is kept to a few thousand characters.
    if (line.size() > kMaxLineSearched) line.remove_prefix(line.size() - kMaxLineSearched);
    if (const auto match = re.first_group(line)) {
      if (!*match) return std::nullopt;
      return in_seconds(**match, adapter.timing.unit);
    }
    if (newline == std::string_view::npos) break;
    end = newline;
  }
  return std::nullopt;
}

}  // namespace raygate

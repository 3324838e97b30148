#include "adapter/reported_time.h"

#include <charconv>
#include <cmath>
#include <regex>
#include <string_view>

#include "adapter/adapter.h"

namespace raygate {
namespace {

std::string describe(std::regex_constants::error_type code) {
  namespace rc = std::regex_constants;
  switch (code) {
    case rc::error_collate: return "invalid collating element";
    case rc::error_ctype: return "invalid character class";
    case rc::error_escape: return "invalid escape or trailing backslash";
    case rc::error_backref: return "invalid back reference";
    case rc::error_brack: return "unmatched '['";
    case rc::error_paren: return "unmatched '(' or ')'";
    case rc::error_brace: return "unmatched '{'";
    case rc::error_badbrace: return "invalid repetition count in '{...}'";
    case rc::error_range: return "invalid character range";
    case rc::error_space: return "too large to compile";
    case rc::error_badrepeat: return "'*', '+', '?' or '{' with nothing to repeat";
    case rc::error_complexity: return "too complex";
    case rc::error_stack: return "too complex";
    default: return "invalid regular expression";
  }
}

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
    const std::regex re(pattern, std::regex::ECMAScript);
    if (re.mark_count() != 1) {
      return "must have exactly one capture group (the number), found " +
             std::to_string(re.mark_count()) + "; write other groups as (?:...)";
    }
  } catch (const std::regex_error& e) {
    return "does not compile: " + describe(e.code());
  }
  return std::nullopt;
}

constexpr std::size_t kMaxLineSearched = 4096;

std::optional<double> parse_reported_seconds(const Adapter& adapter, std::string_view output) {
  if (adapter.timing.source != TimingSource::reported) return std::nullopt;
  const std::regex re(adapter.timing.regex, std::regex::ECMAScript);
  // Line by line from the end: the last report wins, and libstdc++'s recursive matcher never
  // sees a multi-megabyte log as one subject (it can exhaust the stack on long input).
  std::size_t end = output.size();  // one past the current line
  for (;;) {
    const std::size_t newline = end == 0 ? std::string_view::npos : output.rfind('\n', end - 1);
    const std::size_t begin = newline == std::string_view::npos ? 0 : newline + 1;
    std::string_view line = output.substr(begin, end - begin);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    // A line without an end (a progress bar redrawn with \r) can be megabytes: its end holds
    // the report, and the matcher's recursion is kept to a few thousand characters.
    if (line.size() > kMaxLineSearched) line.remove_prefix(line.size() - kMaxLineSearched);
    std::match_results<std::string_view::const_iterator> match;
    if (std::regex_search(line.begin(), line.end(), match, re)) {
      if (!match[1].matched) return std::nullopt;
      return in_seconds(std::string_view(match[1].first, match[1].second), adapter.timing.unit);
    }
    if (newline == std::string_view::npos) break;
    end = newline;
  }
  return std::nullopt;
}

}  // namespace raygate

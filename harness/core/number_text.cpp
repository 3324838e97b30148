#include "core/number_text.h"

#include <fmt/core.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace raygate {
namespace {

// The value as the message quotes it: a paste of 100,000 digits is not echoed whole.
std::string quoted(const std::string& text) {
  constexpr std::size_t kShown = 40;
  if (text.size() <= kShown) return "\"" + text + "\"";
  return fmt::format("\"{}...\" ({} characters)", text.substr(0, kShown), text.size());
}

// The whole text read as a number the way strtold reads it, or nothing when it is not one.
bool read_number(const std::string& text, long double& value) {
  char* end = nullptr;
  errno = 0;
  value = std::strtold(text.c_str(), &end);
  return !text.empty() && end == text.c_str() + text.size();
}

}  // namespace

std::string non_finite_problem(const std::string& text) {
  long double value = 0;
  if (!read_number(text, value)) return "";  // not a number: the caller's parser says so
  if (std::isnan(value)) return quoted(text) + " is not a number (NaN); give a finite one";
  if (std::isinf(value) || !std::isfinite(static_cast<double>(value))) {
    return quoted(text) + " is not a finite number (past a double's range); give a finite one";
  }
  return "";
}

std::string padded_number_problem(const std::string& text) {
  const auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  if (text.empty() || (!space(text.front()) && !space(text.back()))) return "";
  return quoted(text) + " has space around the number; give the number alone";
}

std::string number_problem(const std::string& text, bool whole, double lowest, double highest) {
  const std::string kind = whole ? "a whole number" : "a number";
  const std::string wanted = fmt::format("give {} from {} to {}", kind, lowest, highest);
  if (text.empty()) return fmt::format("the value is empty; {}", wanted);
  if (const std::string problem = padded_number_problem(text); !problem.empty()) return problem;
  long double value = 0;
  if (!read_number(text, value)) return fmt::format("{} is not {}; {}", quoted(text), kind, wanted);
  if (text.find_first_of("xX") != std::string::npos) {
    return fmt::format("{} is hexadecimal; {} in decimal", quoted(text), wanted);
  }
  if (const std::string problem = non_finite_problem(text); !problem.empty()) return problem;
  // Digits only for a count: CLI11 reads "5.0" and "1e1" as no integer, and its Range check then
  // called them out of range.
  if (whole && (std::trunc(value) != value ||
                text.find_first_not_of("+-0123456789 \t") != std::string::npos)) {
    return fmt::format("{} is not a whole number; {}", quoted(text), wanted);
  }
  // Compared as the option will hold it: "0.0001" read as a long double lies below the double
  // 0.0001 that names the range's end, and was refused as out of range.
  if (const double held = static_cast<double>(value); held < lowest || held > highest) {
    return fmt::format("{} is out of range; {}", quoted(text), wanted);
  }
  return "";
}

std::string whole_number_problem(const std::string& text) {
  if (text.empty()) return "";  // empty_value_problem's to say
  const std::size_t digits = text.find_first_not_of("+-");
  if (digits <= 1 && digits < text.size() &&
      text.find_first_not_of("0123456789", digits) == std::string::npos) {
    // Past any 64-bit number (20 digits or more): CLI11's own words were "Could not convert".
    const std::size_t significant = text.find_first_not_of('0', digits);
    const bool huge = significant != std::string::npos && text.size() - significant > 19;
    return huge ? fmt::format("{} is past any count raygate takes; give a smaller whole number",
                              quoted(text))
                : "";
  }
  long double value = 0;
  if (read_number(text, value) && text.find_first_of("xX") != std::string::npos) {
    return fmt::format("{} is hexadecimal; give a whole number in decimal digits", quoted(text));
  }
  return fmt::format("{} is not a whole number; give one in digits", quoted(text));
}

std::string empty_value_problem(const std::string& text) {
  return text.empty() ? "the value is empty; leave the option out for its default" : "";
}

}  // namespace raygate

// Small text helpers for the stages that read system files and tools' output (/proc, /sys,
// uname, compilers): one definition of "blank", so every probe trims the same way.
#pragma once

#include <string_view>

namespace raygate {

// `text` without leading and trailing blanks (space, tab, CR, LF).
constexpr std::string_view trim_blanks(std::string_view text) {
  constexpr std::string_view kBlanks = " \t\r\n";
  const auto first = text.find_first_not_of(kBlanks);
  if (first == std::string_view::npos) return {};
  return text.substr(first, text.find_last_not_of(kBlanks) - first + 1);
}

}  // namespace raygate

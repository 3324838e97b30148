// An enum and its words, both ways, from one table: each stage that prints or reads an enum
// (verdicts, grades, sources, kinds) spells each word once, in a constexpr table next to the
// enum's to_string, instead of once in a switch and again in a parser's list of `if`s.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string_view>
#include <utility>

namespace raygate {

// One row per value of Enum: the value and the word it is written as.
template <typename Enum, std::size_t N>
using EnumWords = std::array<std::pair<Enum, std::string_view>, N>;

// The word of `value`, or `otherwise` for a value the table lacks (a cast from a bad number;
// each enum keeps the fallback word it always had).
template <typename Enum, std::size_t N>
constexpr std::string_view word_of(const EnumWords<Enum, N>& table, Enum value,
                                   std::string_view otherwise = "unknown") {
  for (const auto& [known, word] : table) {
    if (known == value) return word;
  }
  return otherwise;
}

// The value written as `word` (exactly, case and all), or nullopt: the caller names the field.
template <typename Enum, std::size_t N>
constexpr std::optional<Enum> value_of(const EnumWords<Enum, N>& table, std::string_view word) {
  for (const auto& [value, known] : table) {
    if (known == word) return value;
  }
  return std::nullopt;
}

}  // namespace raygate

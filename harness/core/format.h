// Fractions as raygate prints them, in the console, the reports and the gate's reasons: one
// formatter, so "3%" reads the same everywhere.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace raygate {

// 0.079 -> "7.9%" (decimals after the point); "n/a" when not finite.
std::string percent(double fraction, int decimals = 1);
// 0.079 -> "+7.9%", -0.02 -> "-2.0%": a change, its sign always shown; "n/a" when not finite.
std::string signed_percent(double fraction, int decimals = 1);
// A span of time a person reads: "40 s", "3 min", "2.5 h".
std::string duration_text(double seconds);
// A count with its noun: (1, "round") -> "1 round", (17, "round") -> "17 rounds". Nouns whose
// plural is not noun + "s" pass it as `plural`.
std::string count_text(std::size_t count, std::string_view noun, std::string_view plural = {});

}  // namespace raygate

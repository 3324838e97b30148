// What is wrong with a number as a person typed it (an option's value), in words that name the
// value and what would be right. CLI11 reads an INT with its own integer parser, which takes
// "0x10" as 16, and a FLOAT with strtold, which takes "nan" and "inf"; its Range check compares
// with < and >, which NaN passes, and says "Value  not in range" of an empty value. These checks
// run first (cli/subcommand.h, cli/finite_numbers.h), so every number option says one thing.
#pragma once

#include <string>

namespace raygate {

// "" for a finite number, or for text that is not a number at all (the caller's parser says so
// itself); else why it is not finite ("nan", "inf", "1e999").
std::string non_finite_problem(const std::string& text);

// "" unless `text` begins or ends with white space (" 5", "5\n"); strtold skips leading space, so
// a decimal option took " 5" while a count refused it.
std::string padded_number_problem(const std::string& text);

// "" when `text` is a decimal number within [lowest, highest] (a whole one, in digits only, when
// `whole`); else
// what is wrong with it: empty, not a number, hexadecimal, not finite, not whole, or out of range,
// with the range that would be right. Long text is quoted in part.
std::string number_problem(const std::string& text, bool whole, double lowest, double highest);

// "" when `text` is a whole number in digits (an optional sign, digits only), and for ""; else
// what it is instead ("1e9", "2.5", "2x", hexadecimal "0x5"). CLI11 said only "Could not convert",
// or took 0x5 as 5 (cli/finite_numbers.h checks every whole-number option with it).
std::string whole_number_problem(const std::string& text);

// "" for any text but the empty one; for "" that it is empty and what leaving the option out does.
// Every option's value is checked with it (cli/finite_numbers.h): "" quietly meant the default.
std::string empty_value_problem(const std::string& text);

}  // namespace raygate

// Private to the NFF reader: splits NFF text into whitespace-separated tokens with their
// line and column, skips `#` comments, and turns tokens into numbers without locale.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace raygate::nff::detail {

struct Token {
  std::string_view text;  // empty at end of file
  int line = 1;
  int column = 1;

  bool at_end() const { return text.empty(); }
};

// Hands out tokens one at a time. Copyable, so a copy is a cheap one-token look-ahead.
class Lexer {
 public:
  explicit Lexer(std::string_view text);

  Token next();
  Token peek() const { return Lexer(*this).next(); }
  // True when the text holds no token at all (only whitespace and comments).
  bool empty_input() const;

 private:
  void skip_blanks_and_comments();

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_start_ = 0;
  int line_ = 1;
};

// Outcome of reading a token as a number; the caller words the error.
enum class NumberStatus { ok, not_a_number, not_finite };

// A whole-token decimal number ("%g" style, optional leading '+'). NaN, infinities and values
// beyond double's range are not_finite; values too small for a double read as signed zero.
NumberStatus parse_double(std::string_view token, double& value);

// True when the token reads as a number, finite or not: what tells a number from a keyword.
bool is_number(std::string_view token);

// A whole-token decimal integer (optional leading '+') that fits in a long long.
bool parse_integer(std::string_view token, long long& value);

// How an error message shows a found token: `'abc'`, `end of file`, or `byte 0x00` for a
// control byte. Bytes outside printable ASCII never appear raw; long tokens are shortened.
std::string describe(const Token& token);

// Moves `token`'s column to its first control byte, if any, so the message points at it.
Token at_first_control_byte(const Token& token);

}  // namespace raygate::nff::detail

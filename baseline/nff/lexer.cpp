// Tokens and numbers for the NFF reader. NFF is whitespace separated and line structure does
// not matter (spd-spec.md §1.6), so the lexer only keeps lines for locations.
#include "nff/lexer.h"

#include <charconv>
#include <climits>
#include <cmath>
#include <system_error>

namespace raygate::nff::detail {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}

bool is_control(char c) {
  const auto byte = static_cast<unsigned char>(c);
  return byte < 0x20 || byte == 0x7f;
}

int saturate(std::size_t value) {
  return value > static_cast<std::size_t>(INT_MAX) ? INT_MAX : static_cast<int>(value);
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// from_chars rejects a leading '+', which hand-written files may use.
std::string_view strip_plus(std::string_view token) {
  if (token.size() >= 2 && token[0] == '+' && (is_digit(token[1]) || token[1] == '.')) {
    token.remove_prefix(1);
  }
  return token;
}

// For a token from_chars called out of range: true when its magnitude is below 1 (an
// underflow, read as zero) rather than above (an overflow). Uses the decimal exponent of the
// leading non-zero digit plus the written exponent; out of range means far from 1 either way.
bool is_underflow(std::string_view token) {
  std::size_t i = (!token.empty() && token[0] == '-') ? 1 : 0;
  bool found = false;
  bool after_point = false;
  long long integer_digits = 0;  // from the leading non-zero digit to the point
  long long fraction_zeros = 0;  // zeros between the point and the leading non-zero digit
  for (; i < token.size() && token[i] != 'e' && token[i] != 'E'; ++i) {
    const char c = token[i];
    if (c == '.') {
      after_point = true;
    } else if (!after_point) {
      found = found || c != '0';
      if (found) ++integer_digits;
    } else if (!found) {
      found = c != '0';
      if (!found) ++fraction_zeros;
    }
  }
  const long long leading = integer_digits > 0 ? integer_digits - 1 : -(fraction_zeros + 1);
  long long written = 0;
  if (i + 1 < token.size()) {
    const std::string_view digits = strip_plus(token.substr(i + 1));
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), written);
    if (result.ec == std::errc::result_out_of_range) {
      written = digits[0] == '-' ? LLONG_MIN / 2 : LLONG_MAX / 2;
    }
  }
  return leading + written < 0;
}

}  // namespace

Lexer::Lexer(std::string_view text) : text_(text) {
  // A UTF-8 byte order mark, as some Windows editors write, is not part of the first token.
  if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = line_start_ = 3;
}

void Lexer::skip_blanks_and_comments() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++pos_;
      if (line_ < INT_MAX) ++line_;  // saturates rather than overflowing on absurd input
      line_start_ = pos_;
    } else if (is_blank(c)) {
      ++pos_;
    } else if (c == '#') {
      while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    } else {
      return;
    }
  }
}

Token Lexer::next() {
  skip_blanks_and_comments();
  Token token;
  token.line = line_;
  token.column = saturate(pos_ - line_start_ + 1);
  const std::size_t start = pos_;
  // A '#' ends a token too: a comment may follow a number without a space.
  while (pos_ < text_.size() && !is_blank(text_[pos_]) && text_[pos_] != '#') ++pos_;
  token.text = text_.substr(start, pos_ - start);
  return token;
}

bool Lexer::empty_input() const { return Lexer(text_).next().at_end(); }

NumberStatus parse_double(std::string_view token, double& value) {
  token = strip_plus(token);
  const char* end = token.data() + token.size();
  double parsed = 0.0;
  const auto [ptr, ec] = std::from_chars(token.data(), end, parsed, std::chars_format::general);
  if (ptr != end || ec == std::errc::invalid_argument) return NumberStatus::not_a_number;
  if (ec == std::errc::result_out_of_range) {
    if (!is_underflow(token)) return NumberStatus::not_finite;
    value = token[0] == '-' ? -0.0 : 0.0;
    return NumberStatus::ok;
  }
  if (!std::isfinite(parsed)) return NumberStatus::not_finite;
  value = parsed;
  return NumberStatus::ok;
}

bool is_number(std::string_view token) {
  double ignored = 0.0;
  return parse_double(token, ignored) != NumberStatus::not_a_number;
}

bool parse_integer(std::string_view token, long long& value) {
  token = strip_plus(token);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && ptr == end;
}

std::string describe(const Token& token) {
  if (token.at_end()) return "end of file";
  static constexpr char hex[] = "0123456789abcdef";
  for (const char c : token.text) {
    if (is_control(c)) {
      const auto byte = static_cast<unsigned char>(c);
      return std::string("byte 0x") + hex[byte >> 4] + hex[byte & 15];
    }
  }
  constexpr std::size_t max_shown = 40;
  std::string shown = "'";
  for (std::size_t i = 0; i < token.text.size() && i < max_shown; ++i) {
    const auto byte = static_cast<unsigned char>(token.text[i]);
    if (byte >= 0x80) {
      shown += "\\x";
      shown += hex[byte >> 4];
      shown += hex[byte & 15];
    } else {
      shown += static_cast<char>(byte);
    }
  }
  if (token.text.size() > max_shown) shown += "...";
  return shown + "'";
}

Token at_first_control_byte(const Token& token) {
  Token moved = token;
  for (std::size_t i = 0; i < token.text.size(); ++i) {
    if (is_control(token.text[i])) {
      moved.column = saturate(static_cast<std::size_t>(token.column) + i);
      break;
    }
  }
  return moved;
}

}  // namespace raygate::nff::detail

// An adapter's timing.regex, compiled and matched by PCRE2 with bounds. std::regex has none: a
// repeated group that repeats ((a+)+$ against 37 characters) backtracked for ever, deaf to
// --max-minutes and SIGTERM, and 20,000 nested groups overflowed the stack while compiling (a
// sweep). PCRE2 counts its work: a match that needs more than kMatchLimit steps stops with an
// error raygate reports, and nesting past PCRE2's limit does not compile. The syntax is Perl's,
// which is ECMAScript's for what a time needs: (?:...), \d, \s, [0-9.]+, anchors.
#pragma once

#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace raygate {

// A match that needed more backtracking than the bound allows: the pattern, not the tracer.
class RegexTooCostly : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class TimingRegex {
 public:
  // Steps of PCRE2's matcher in one search of one line (its match limit): a timing line takes
  // hundreds; a pattern that needs this many is backtracking exponentially or cubically.
  static constexpr unsigned kMatchLimit = 200000;

  // Throws std::invalid_argument with raygate's words: "does not compile: <PCRE2's reason> at
  // character N".
  explicit TimingRegex(const std::string& pattern);
  ~TimingRegex();
  TimingRegex(const TimingRegex&) = delete;
  TimingRegex& operator=(const TimingRegex&) = delete;

  std::size_t capture_groups() const;

  // Searches `line`: nullopt when the pattern does not match, an empty optional inside when it
  // matched without setting group 1, else group 1's text. Throws RegexTooCostly past the limit.
  std::optional<std::optional<std::string_view>> first_group(std::string_view line) const;

 private:
  struct Handles;
  std::unique_ptr<Handles> handles_;
};

}  // namespace raygate

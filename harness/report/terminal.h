// How raygate talks to people on a terminal (docs/cli.md): standard output carries results, and
// only when a command was asked for them; progress, what is being done and where files went go
// to standard error. Colour follows --color auto|always|never, with NO_COLOR honoured
// (https://no-color.org); --quiet drops the chatter. cli/console.h builds a Console from the
// root command's options.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>
#include <string_view>

#include "core/message_sink.h"
#include "core/sanitize.h"

namespace raygate {

enum class ColourChoice { automatic, always, never };

ColourChoice parse_colour_choice(std::string_view text);

// --color always and never win; auto colours a terminal unless NO_COLOR is set to a non-empty
// value (`no_color` is its value, nullptr when unset: an empty NO_COLOR does not count).
bool colour_wanted(ColourChoice choice, bool terminal, const char* no_color);

bool is_terminal(std::FILE* stream);

// What raygate says on standard error: chatter, warnings, and what library steps say
// (core/message_sink.h).
class Console final : public MessageSink {
 public:
  Console(ColourChoice choice, bool quiet, const char* no_color)
      : choice_(choice), quiet_(quiet), no_color_(no_color != nullptr && *no_color != '\0') {}

  // Whether to colour what goes to `stream` (nullptr: a file, coloured only with --color always).
  bool colour(std::FILE* stream) const;
  bool quiet() const { return quiet_; }
  // A line of chatter on standard error (what is done, where a file went); --quiet drops it.
  // Both made terminal-safe (core/sanitize.h): they may quote a commit's or a tracer's text.
  void info(const std::string& text) const override;
  // A warning on standard error; kept with --quiet.
  void warning(const std::string& text) const override;
  // Lines on standard error as given; kept with --quiet.
  void problem(const std::string& text) const override;

 private:
  ColourChoice choice_;
  bool quiet_;
  bool no_color_;
};

// A message cut to a length a CI log and a terminal stay readable at: what a user pasted (a
// 100,000-character --rev, a value for a number) is echoed back only as far as it helps. Long
// enough for any message raygate itself composes (a build's log tail included). A word of over
// 240 bytes (a path) is shown by its first and last 100 and its length.
std::string bounded_message(std::string text);

// A command-line parser's words where a user stops at them: CLI11's "--x: At Most 1 required but
// received 2" becomes "--x is given 2 times; give it once", and "--a excludes --b" becomes "--a
// and --b cannot be given together; give one". Other text is returned as it is.
std::string plain_usage_words(std::string text);

// The last words of a command (its error, or what an interrupt kept), bounded, on standard
// error. Never throws: after a hang-up the terminal is gone and every write fails (EIO), and
// the exit code must still say what happened.
void say_last_words(const std::string& line);

// A command's result on standard output: `json()` (indented one space) with --format json, else
// `text()`; only the one asked for is computed. The JSON boundary repairs invalid UTF-8 (a store
// may hold it) to U+FFFD instead of throwing; text is made safe for a terminal.
template <typename Json, typename Text>
void print_result(const std::string& format, Json json, Text text) {
  if (format == "json") {
    const std::string dumped = json().dump(1, ' ', false, nlohmann::json::error_handler_t::replace);
    std::fputs((dumped + "\n").c_str(), stdout);
  } else {
    std::fputs(terminal_text(std::string(text())).c_str(), stdout);
  }
}

}  // namespace raygate

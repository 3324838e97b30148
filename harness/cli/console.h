// How raygate talks to people (docs/cli.md): standard output carries results, and only when a
// command was asked for them; progress, what is being done and where files went go to standard
// error. The global --color auto|always|never (with NO_COLOR honoured, https://no-color.org)
// and --quiet live on the root command; a subcommand reads them with console_of(), so no state
// is global. Also the one way to keep an old flag spelling as a deprecated alias.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>
#include <string_view>

#include "core/sanitize.h"

namespace raygate::cli {

enum class ColourChoice { automatic, always, never };

ColourChoice parse_colour_choice(std::string_view text);

// --color always and never win; auto colours a terminal unless NO_COLOR is set to a non-empty
// value (`no_color` is its value, nullptr when unset: an empty NO_COLOR does not count).
bool colour_wanted(ColourChoice choice, bool terminal, const char* no_color);

// --color, --quiet and --config on the root; subcommands accept them after their own name too.
void add_global_options(CLI::App& app);

class Console {
 public:
  Console(ColourChoice choice, bool quiet, const char* no_color)
      : choice_(choice), quiet_(quiet), no_color_(no_color != nullptr && *no_color != '\0') {}

  // Whether to colour what goes to `stream` (nullptr: a file, coloured only with --color always).
  bool colour(std::FILE* stream) const;
  bool quiet() const { return quiet_; }
  // A line of chatter on standard error (what is done, where a file went); --quiet drops it.
  // Both made terminal-safe (core/sanitize.h): they may quote a commit's or a tracer's text.
  void info(const std::string& text) const;
  // A warning on standard error; kept with --quiet.
  void warning(const std::string& text) const;

 private:
  ColourChoice choice_;
  bool quiet_;
  bool no_color_;
};

// The console of the command line `command` belongs to: its root's --color and --quiet, and
// the environment's NO_COLOR.
Console console_of(const CLI::App& command);

// `old_name` as a deprecated spelling of the option `current` (already added): the same
// variable, listed under "Deprecated" in --help, exclusive with `current`, and a one-line note on standard
// error when used.
CLI::Option* add_deprecated_alias(CLI::App& command, const std::string& old_name,
                                  CLI::Option* current, std::string& variable);

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

// --format FORMAT for what a command prints on standard output (`formats`, the first the
// default), with the deprecated --json flag meaning --format json.
CLI::Option* add_format_option(CLI::App& command, std::string& format,
                               const std::vector<std::string>& formats, bool json_alias = false);

}  // namespace raygate::cli

// How a subcommand is put together, once for all of them: its options bind into a fresh Args
// record, and when it is the command given, its function runs on that record and returns
// raygate's exit code. Also the shape most numeric options share (a range, the default shown).
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <type_traits>

#include "cli/console.h"
#include "core/number_text.h"
#include "pipeline/output_failures.h"

namespace raygate::cli {

// Binds `command` to a fresh Args record and returns it for the options to bind into. The
// record is owned by the command's callback (CLI11 keeps the addresses of its fields until
// parsing is done), so it lives as long as the application. Once parsed, `run(args)` or
// `run(args, console)` (the root's --color and --quiet: console_of) leaves its exit code in
// `exit_code`.
template <typename Args, typename Run>
Args& bind_command(CLI::App& command, Run run, int& exit_code) {
  auto args = std::make_shared<Args>();
  command.callback([args, &command, run, &exit_code] {
    if constexpr (std::is_invocable_v<Run, const Args&, const Console&>) {
      exit_code = run(*args, console_of(command));
    } else {
      exit_code = run(*args);
    }
  });
  return *args;
}

// A subcommand of a subcommand (scenes list, golden verify, adapter check) and its record: `name`
// under `parent`, bound as above. (The top-level commands are named in main.cpp's table.)
template <typename Args>
struct Subcommand {
  CLI::App* command;
  Args* args;
};

template <typename Args, typename Run>
Subcommand<Args> add_subcommand(CLI::App& parent, const std::string& name, const std::string& help,
                                Run run, int& exit_code) {
  CLI::App* command = parent.add_subcommand(name, help);
  return {command, &bind_command<Args>(*command, run, exit_code)};
}

// A number held to [low, high], its default shown in --help. The bounds' type is the one
// --help names (INT or FLOAT), so pass them as the option's own kind of number. raygate's words
// check first (an empty value, NaN, 0x10, a fraction of a count: core/number_text.h); CLI::Range
// then only writes --help's "INT in [low - high]".
template <typename Value, typename Bound>
CLI::Option* add_bounded_option(CLI::App& command, const std::string& name, Value& value, Bound low,
                                Bound high, const std::string& help) {
  const auto problem = [=](const std::string& text) {
    return number_problem(text, std::is_integral_v<Value>, double(low), double(high));
  };
  return command.add_option(name, value, help)
      ->check(CLI::Validator(problem, "", "NUMBER"))
      ->check(CLI::Range(low, high))
      ->capture_default_str();
}

// Paths a command writes, refused when the command line is parsed (exit 2, the option named), not
// found unwritable once the work is done (pipeline/output_failures.h). "-" is standard output.
inline CLI::Validator writable_file() { return {output_document_problem, "", "WRITABLE FILE"}; }
inline CLI::Validator writable_folder() { return {output_folder_problem, "", "WRITABLE FOLDER"}; }

}  // namespace raygate::cli

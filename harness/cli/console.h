// The command line's side of how raygate talks to people (report/terminal.h): the global --color
// and --quiet live on the root command and a subcommand reads them with console_of(), so no
// state is global. Also --format for a command's result, and the one way to keep an old flag
// spelling as a deprecated alias.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "report/terminal.h"

namespace raygate::cli {

// --color, --quiet and --config on the root; subcommands accept them after their own name too.
void add_global_options(CLI::App& app);

// The console of the command line `command` belongs to: its root's --color and --quiet, and
// the environment's NO_COLOR.
Console console_of(const CLI::App& command);

// `old_name` as a deprecated spelling of the option `current` (already added): the same
// variable, listed under "Deprecated" in --help, exclusive with `current`, and a one-line note
// on standard error when used.
CLI::Option* add_deprecated_alias(CLI::App& command, const std::string& old_name,
                                  CLI::Option* current, std::string& variable);

// --format FORMAT for what a command prints on standard output (`formats`, the first the
// default), with the deprecated --json flag meaning --format json.
CLI::Option* add_format_option(CLI::App& command, std::string& format,
                               const std::vector<std::string>& formats, bool json_alias = false);

}  // namespace raygate::cli

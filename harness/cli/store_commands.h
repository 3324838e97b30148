// The subcommands over the results store besides `history` (cmd_history.cpp registers them all
// through add_history_commands in commands.h): import and export of results documents.
#pragma once

#include <CLI/CLI.hpp>

namespace raygate::cli {

void add_import_command(CLI::App& app, int& exit_code);
void add_export_command(CLI::App& app, int& exit_code);

}  // namespace raygate::cli

// The project's defaults (pipeline/project_config.h reads them from RAYGATE_* variables and
// raygate.toml) made the defaults of the options of that name (docs/cli.md): the command line
// still wins over them.
#pragma once

#include <CLI/CLI.hpp>

#include "pipeline/project_config.h"

namespace raygate::cli {

// Makes each default the value of the options of that name in every subcommand (a required
// option is then no longer required), except where the name is a filter over stored results
// (history's and alert's --adapter and --suite). A value the option's check refuses (a policy
// file that does not exist) is a UsageError naming the origin, raised once parsing is done and
// only when the command parsed is one that takes the option and the command line did not give it:
// --version, --help and every other command still work.
void apply_project_defaults(CLI::App& app, const ProjectDefaults& defaults);

}  // namespace raygate::cli

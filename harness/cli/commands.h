// One function per subcommand: main.cpp's table names each command and says what it does
// (--help); the function binds the command's options (bind_command, cli/subcommand.h) and, when
// it is the one given, runs it and leaves its exit code in `exit_code`. Errors travel up as
// raygate::Error to main().
#pragma once

#include <CLI/CLI.hpp>

namespace raygate::cli {

void add_scenes_command(CLI::App& command, int& exit_code);  // list, generate, convert
void add_golden_command(CLI::App& command, int& exit_code);  // verify, bless
void add_validate_command(CLI::App& command, int& exit_code);
void add_adapter_command(CLI::App& command, int& exit_code);    // check
void add_calibrate_command(CLI::App& command, int& exit_code);  // a suite sized to a tracer
void add_run_command(CLI::App& command, int& exit_code);
void add_history_command(CLI::App& command, int& exit_code);
void add_import_command(CLI::App& command, int& exit_code);
void add_export_command(CLI::App& command, int& exit_code);
void add_compare_command(CLI::App& command, int& exit_code);
void add_gate_command(CLI::App& command, int& exit_code);
void add_bisect_command(CLI::App& command, int& exit_code);
void add_report_command(CLI::App& command, int& exit_code);
void add_consistency_command(CLI::App& command, int& exit_code);  // ratios across machines
void add_doctor_command(CLI::App& command, int& exit_code);       // is this machine fit to measure
void add_merge_command(CLI::App& command, int& exit_code);        // shards of a CI matrix
void add_alert_command(CLI::App& command, int& exit_code);    // change points on a branch's history
void add_scaling_command(CLI::App& command, int& exit_code);  // growth exponents per family

}  // namespace raygate::cli

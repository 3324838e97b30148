// raygate: measures ray tracers against a fixed baseline tracer on the SPD scenes and gates merges
// on the normalized ratio. This file names the subcommands (a table, as ninja's kTools) and maps
// errors to exit codes.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/finite_numbers.h"
#include "cli/project_config.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/interrupt.h"
#include "core/sanitize.h"
#include "core/strays.h"
#include "pipeline/output_failures.h"
#include "report/reporter.h"
#include "report/terminal.h"

namespace {

namespace cli = raygate::cli;
using raygate::bounded_message;
using raygate::say_last_words;

// A subcommand as `raygate --help` lists it, and the function that binds its options.
struct Command {
  const char* name;
  std::string help;
  void (*add)(CLI::App& command, int& exit_code);
};

// Every subcommand, in the order `raygate --help` lists them: the inputs, measuring and the
// documents, then across documents and machines, and history's alerts and growth.
std::vector<Command> commands() {
  return {
      {"scenes", "list, generate and convert SPD scenes (NFF; POV-Ray, OBJ, pbrt-v4)",
       cli::add_scenes_command},
      {"golden", "verify or bless golden images: the baseline's, or a tracer's from a run",
       cli::add_golden_command},
      {"validate", "compare the baseline's SPD ray counts with the published SPD statistics",
       cli::add_validate_command},
      {"adapter", "check adapter files (adapters/README.md)", cli::add_adapter_command},
      {"calibrate",
       "size a suite to a tracer: resolutions at which each render takes a target time",
       cli::add_calibrate_command},
      {"run", "measure one revision against the baseline on a suite; writes a results document",
       cli::add_run_command},
      {"history", "normalized ratio and image error per scene over commits, from the store",
       cli::add_history_command},
      {"import", "store results documents (a document already stored is kept once)",
       cli::add_import_command},
      {"export", "write stored results documents as JSON (newest first), as they were stored",
       cli::add_export_command},
      {"compare", "measure base and head in the same job and gate the change",
       cli::add_compare_command},
      {"gate", "judge a results document under a policy; the exit code says",
       cli::add_gate_command},
      {"bisect", "find the first commit that made a scene slower (or its image wrong)",
       cli::add_bisect_command},
      {"report",
       "write the gate's verdict on a results document as " + raygate::report_format_list(),
       cli::add_report_command},
      {"consistency",
       "are the tracer's ratios the same on other machines? r² and per-scene deviation over "
       "the results documents of one tracer revision",
       cli::add_consistency_command},
      {"doctor",
       "is this machine fit to measure? governor, turbo, load, CPUs, SMT, perf, ASLR, swap, VM, "
       "and a measured noise score",
       cli::add_doctor_command},
      {"merge", "join the results documents of a CI matrix's shards (--shard K/N) and gate them",
       cli::add_merge_command},
      {"alert",
       "flag slowdowns and memory steps that landed: change points in each series' history",
       cli::add_alert_command},
      {"scaling", "fit how time grows with scene size per scene family; judge a compare's change",
       cli::add_scaling_command}};
}

// A parse error, "raygate: error:" as any: CLI11's words, bounded, an unknown command named.
std::string usage_failure(const CLI::App* command, const CLI::Error& e) {
  const bool unknown = command->get_parent() == nullptr && command->get_subcommands().empty() &&
                       !command->remaining().empty();
  return bounded_message(
      "raygate: error: " +
      (unknown ? "unknown command '" + raygate::terminal_text(command->remaining()[0]) +
                     "'\nRun with --help for the commands.\n"
               : raygate::plain_usage_words(CLI::FailureMessage::simple(command, e))));
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"raygate: ray tracer regression harness, normalized against a baseline tracer"};
  app.require_subcommand(1);
  // The commit tells two builds of one version apart (cmake/RaygateGitCommit.cmake).
  app.set_version_flag(
      "--version", std::string("raygate ") + RAYGATE_VERSION + " (git " + RAYGATE_GIT_COMMIT + ")");
  // Before any child starts: SIGINT, SIGTERM, SIGHUP, SIGQUIT stop children and keep what was
  // measured; orphans re-parent to raygate, to be swept (core/interrupt.h, core/strays.h).
  raygate::install_interrupt_handlers();
  raygate::become_subreaper();
  cli::add_global_options(app);
  int exit_code = 0;
  for (const Command& command : commands()) {
    command.add(*app.add_subcommand(command.name, command.help), exit_code);
  }
  cli::refuse_empty_and_non_finite_values(app);
  app.failure_message(usage_failure);
  try {
    // Before parsing: the command line overrides these (cli/project_config.h).
    cli::apply_project_defaults(
        app, raygate::load_project_defaults(raygate::find_config_argument(argc, argv)));
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return raygate::exit_code_after_standard_output(app.exit(e));  // --help, --version
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return raygate::to_int(raygate::ExitCode::usage);
  } catch (const raygate::Interrupted& e) {
    // One line: what was kept, and where. Messages quote revisions, branch names and paths: a
    // terminal must not obey their bytes.
    say_last_words(fmt::format("raygate: {}", raygate::terminal_text(e.what())));
    return raygate::to_int(e.code());
  } catch (const raygate::Error& e) {
    say_last_words(fmt::format("raygate: error: {}", raygate::terminal_text(e.what())));
    return raygate::to_int(e.code());
  } catch (const std::filesystem::filesystem_error& e) {  // a path too long 2, else 3, said on what
    const raygate::FilesystemFailure failure = raygate::filesystem_failure(e);
    say_last_words("raygate: error: " + raygate::terminal_text(failure.message));
    return failure.exit_code;
  } catch (const std::exception& e) {
    say_last_words(fmt::format("raygate: internal error: {}", raygate::terminal_text(e.what())));
    return raygate::to_int(raygate::ExitCode::infrastructure);
  }
  exit_code = raygate::exit_code_after_standard_output(exit_code);
  if (const int sig = raygate::interrupt_signal(); sig != 0) {
    // The signal came after the last child ended: the work is done and kept, but the caller
    // asked to stop and learns that it did.
    const raygate::Interrupted stop(sig, "");
    say_last_words(
        fmt::format("raygate: interrupted by {} after the work was done; all of it was kept",
                    raygate::signal_name(sig)));
    return raygate::to_int(stop.code());
  }
  return exit_code;
}

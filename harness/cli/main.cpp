// raygate: measures ray tracers against a fixed baseline tracer on the SPD scenes and gates
// merges on the normalized ratio. This file only wires subcommands and maps errors to exit codes.
#include <fmt/core.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <string>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/project_config.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/interrupt.h"
#include "core/sanitize.h"
#include "core/strays.h"

namespace {

using AddCommand = void (*)(CLI::App& app, int& exit_code);

// Every subcommand, in the order `raygate --help` lists them: the inputs (scenes, goldens,
// adapters), measuring (run, compare, bisect), the documents (history, gate, report), then across
// documents and machines (consistency, doctor, merge), and history's alerts and growth (alert,
// scaling).
constexpr AddCommand kCommands[] = {
    raygate::cli::add_scenes_command,      raygate::cli::add_golden_command,
    raygate::cli::add_validate_command,    raygate::cli::add_adapter_command,
    raygate::cli::add_run_command,         raygate::cli::add_history_commands,
    raygate::cli::add_compare_command,     raygate::cli::add_gate_command,
    raygate::cli::add_bisect_command,      raygate::cli::add_report_command,
    raygate::cli::add_consistency_command, raygate::cli::add_doctor_command,
    raygate::cli::add_merge_command,       raygate::cli::add_alert_command,
    raygate::cli::add_scaling_command};

// The last words, on standard error. Never throws: after a hang-up the terminal is gone and
// every write fails (EIO), and the exit code must still say what happened.
void say(const std::string& line) {
  std::fputs((line + "\n").c_str(), stderr);
  std::fflush(stderr);
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"raygate: ray tracer regression harness, normalized against a baseline tracer"};
  app.require_subcommand(1);
  // The commit tells two builds of one version apart (cmake/RaygateGitCommit.cmake).
  app.set_version_flag("--version", std::string("raygate ") + RAYGATE_VERSION + " (git " +
                                        RAYGATE_GIT_COMMIT + ")");
  // Before any child starts: Ctrl-C, SIGTERM and SIGHUP stop children and write what was
  // measured, and orphans of children re-parent to raygate, to be swept (core/interrupt.h,
  // core/strays.h).
  raygate::install_interrupt_handlers();
  raygate::become_subreaper();
  raygate::cli::add_global_options(app);
  int exit_code = 0;
  for (const AddCommand add : kCommands) add(app, exit_code);
  try {
    // Before parsing: the command line overrides these (cli/project_config.h).
    raygate::cli::apply_project_defaults(
        app, raygate::load_project_defaults(raygate::find_config_argument(argc, argv)));
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return raygate::to_int(raygate::ExitCode::usage);
  } catch (const raygate::Interrupted& e) {
    // One line: what was kept, and where. Messages quote revisions, branch names and paths: a
    // terminal must not obey their bytes.
    say(fmt::format("raygate: {}", raygate::terminal_text(e.what())));
    return raygate::to_int(e.code());
  } catch (const raygate::Error& e) {
    say(fmt::format("raygate: error: {}", raygate::terminal_text(e.what())));
    return raygate::to_int(e.code());
  } catch (const std::exception& e) {
    say(fmt::format("raygate: internal error: {}", raygate::terminal_text(e.what())));
    return raygate::to_int(raygate::ExitCode::infrastructure);
  }
  if (const int sig = raygate::interrupt_signal(); sig != 0) {
    // The signal came after the last child ended: the work is done and kept, but the caller
    // asked to stop and learns that it did.
    const raygate::Interrupted stop(sig, "");
    say(fmt::format("raygate: interrupted by {} after the work was done; all of it was kept",
                    raygate::signal_name(sig)));
    return raygate::to_int(stop.code());
  }
  return exit_code;
}

// `raygate doctor`: is this machine fit to measure, and what should change? Checks the CPU
// governor, turbo, load, usable CPUs, SMT, perf counters, ASLR, swap and virtualization
// (harness/doctor/), then measures a noise score with raygate-baseline in A/A pairs. Advice
// only: exit 0 whenever it could check, 3 when the baseline could not run, 2 for bad options.
#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/subcommand.h"
#include "core/exit_codes.h"
#include "doctor/doctor_report.h"
#include "pipeline/document_commands.h"

namespace raygate::cli {
namespace {

struct DoctorArgs {
  std::string format;  // text, json
  int rounds = kDefaultNoiseRounds;
  std::string baseline;
};

int doctor_command(const DoctorArgs& args) {
  const bool chatty = args.format != "json";
  const DoctorReport report =
      examine_machine(args.rounds, args.baseline, [chatty](const std::string& line) {
        if (chatty) fmt::print(stderr, "{}\n", line);
      });
  print_result(
      args.format, [&] { return doctor_json(report); }, [&] { return doctor_text(report); });
  return report.noise ? to_int(ExitCode::pass) : to_int(ExitCode::infrastructure);
}

}  // namespace

void add_doctor_command(CLI::App& command, int& exit_code) {
  DoctorArgs& args = bind_command<DoctorArgs>(command, doctor_command, exit_code);
  add_format_option(command, args.format, {"text", "json"}, true);
  add_bounded_option(command, "--rounds", args.rounds, 2, 100000,
                     "A/A pairs of raygate-baseline runs for the noise score");
  command.add_option("--baseline", args.baseline,
                     "raygate-baseline executable (default: beside raygate)");
}

}  // namespace raygate::cli

// `raygate validate`: the baseline's SPD ray counts against the published SPD statistics
// (pipeline/spd_validation.h). Exit 0 when every count is within the tolerance, 1 otherwise.
#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/subcommand.h"
#include "core/exit_codes.h"
#include "core/fs.h"
#include "pipeline/spd_validation.h"

namespace raygate::cli {
namespace {

struct ValidateArgs {
  SpdValidationRequest request;
  std::string markdown;
};

int run_validate(const ValidateArgs& args) {
  const SpdValidation validation = validate_spd_counts(
      args.request, [](const std::string& line) { fmt::print(stderr, "{}\n", line); });
  fmt::print("{}", validation.table);
  if (!args.markdown.empty()) write_file_atomically(args.markdown, validation.table);
  return validation.all_within ? 0 : to_int(ExitCode::regression);
}

}  // namespace

void add_validate_command(CLI::App& command, int& exit_code) {
  ValidateArgs& args = bind_command<ValidateArgs>(command, run_validate, exit_code);
  command.add_option("scenes", args.request.scenes, "Classic scenes to check (default: all seven)");
  command.add_option("--accel", args.request.accel, "none or bbox (same counts; bbox is faster)")
      ->capture_default_str();
  command.add_option("--work-dir", args.request.work_dir, "Where scenes and renders go")
      ->capture_default_str()
      ->check(writable_folder());
  command.add_option("--markdown", args.markdown, "Also write the table to this file")
      ->check(writable_file());
  command.add_option("--baseline", args.request.baseline,
                     "raygate-baseline to use (default: beside raygate)");
}

}  // namespace raygate::cli

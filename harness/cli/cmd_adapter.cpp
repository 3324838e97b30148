// `raygate adapter check FILE...`: validates adapter files and shows what raygate will run,
// placeholders and all, so a user can read an adapter back before a CI job trips over it.
// Exit 0 when every file is valid, 2 when any is not (each problem is printed, not just the
// first file's). Missing Debian packages are a warning: the build may still find its tools.
#include <fmt/core.h>

#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/subcommand.h"
#include "core/exit_codes.h"
#include "pipeline/adapter_check.h"

namespace raygate::cli {
namespace {

using AdapterFiles = std::vector<std::string>;

int run_check(const AdapterFiles& files) {
  int invalid = 0;
  for (const std::string& file : files) {
    const AdapterCheck check = check_adapter_file(file);
    if (!check.error.empty()) {
      fmt::print(stderr, "raygate: error: {}\n", check.error);
      ++invalid;
      continue;
    }
    fmt::print("{}", check.summary);
    if (!check.warning.empty()) fmt::print(stderr, "raygate: warning: {}\n", check.warning);
  }
  return invalid == 0 ? to_int(ExitCode::pass) : to_int(ExitCode::usage);
}

}  // namespace

void add_adapter_command(CLI::App& command, int& exit_code) {
  command.require_subcommand(1);
  const auto [check, files] = add_subcommand<AdapterFiles>(
      command, "check", "validate adapter files and show the commands raygate would run", run_check,
      exit_code);
  check->add_option("files", *files, "Adapter JSON files")->required();
}

}  // namespace raygate::cli

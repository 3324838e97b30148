// `raygate adapter check FILE...`: validates adapter files and shows what raygate will run,
// placeholders and all, so a user can read an adapter back before a CI job trips over it.
// Exit 0 when every file is valid, 2 when any is not (each problem is printed, not just the
// first file's). Missing Debian packages are a warning: the build may still find its tools.
#include <fmt/core.h>

#include <memory>
#include <string>
#include <vector>

#include "adapter/adapter.h"
#include "adapter/packages.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "pipeline/adapter_summary.h"

namespace raygate::cli {
namespace {

void warn_missing_packages(const Adapter& a) {
  try {
    const std::vector<std::string> missing = missing_packages(a);
    if (missing.empty()) return;
    std::string list;
    for (const std::string& p : missing) list += (list.empty() ? "" : ", ") + p;
    fmt::print(stderr, "raygate: warning: {}: Debian packages not installed: {}\n",
               a.file.string(), list);
    fmt::print(stderr, "  install them with: {}\n", apt_get_line(missing));
  } catch (const InfraError& e) {
    fmt::print(stderr, "raygate: warning: {}: cannot check \"requires\": {}\n", a.file.string(),
               e.what());
  }
}

int run_check(const std::vector<std::string>& files) {
  int invalid = 0;
  for (const std::string& file : files) {
    try {
      const Adapter adapter = load_adapter(file);
      fmt::print("{}", adapter_summary(adapter));
      warn_missing_packages(adapter);
    } catch (const UsageError& e) {
      fmt::print(stderr, "raygate: error: {}\n", e.what());
      ++invalid;
    }
  }
  return invalid == 0 ? to_int(ExitCode::pass) : to_int(ExitCode::usage);
}

}  // namespace

void add_adapter_command(CLI::App& app, int& exit_code) {
  CLI::App* adapter = app.add_subcommand("adapter", "Work with adapter files (adapters/README.md)");
  adapter->require_subcommand(1);
  auto files = std::make_shared<std::vector<std::string>>();
  CLI::App* check = adapter->add_subcommand(
      "check", "Validate adapter files and show the commands raygate would run");
  check->add_option("files", *files, "Adapter JSON files")->required();
  check->callback([files, &exit_code] { exit_code = run_check(*files); });
}

}  // namespace raygate::cli

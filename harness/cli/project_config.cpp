#include "cli/project_config.h"

#include <fmt/core.h>

#include <algorithm>

#include "core/error.h"
#include "store/postgres_url.h"

namespace raygate::cli {

namespace {

// Subcommands where an option of a project key's name filters stored results rather than
// naming what to use: the project's adapter should not hide other adapters' history.
bool is_filter(const std::string& subcommand, const std::string& key) {
  return (subcommand == "history" || subcommand == "alert") && (key == "adapter" || key == "suite");
}

// A default an option's check refused (a policy file that does not exist): an error only for the
// command that would use it, so `raygate --version` or `adapter check` still work.
struct RefusedDefault {
  const CLI::App* command;
  const CLI::Option* option;
  std::string message;
};

void apply_to_subcommands(CLI::App& app, const ProjectDefaults& defaults,
                          std::vector<RefusedDefault>& refused) {
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
    apply_to_subcommands(*command, defaults, refused);
    for (const auto& [key, value] : defaults) {
      CLI::Option* option = command->get_option_no_throw("--" + key);
      if (option == nullptr || is_filter(command->get_name(), key)) continue;
      try {
        option->run_callback_for_default()->default_val(value.value);
        if (key == "store") option->default_str(redact_postgresql_url(value.value));  // --help
      } catch (const CLI::Error& e) {
        refused.push_back(
            {command, option,
             fmt::format("{}: {} {}: {}", value.origin, command->get_name(), key, e.what())});
      }
      option->required(false);
    }
  }
}

}  // namespace

void apply_project_defaults(CLI::App& app, const ProjectDefaults& defaults) {
  if (defaults.empty()) return;
  std::vector<RefusedDefault> refused;
  apply_to_subcommands(app, defaults, refused);
  if (refused.empty()) return;
  // Runs once parsing is done, before any command's own callback: a refused default matters
  // only to the command given, and only when its option was not given on the command line.
  app.parse_complete_callback([refused] {
    for (const RefusedDefault& r : refused) {
      if (r.command->parsed() && r.option->count() == 0) throw UsageError(r.message);
    }
  });
}

}  // namespace raygate::cli

#include "cli/console.h"

#include <fmt/core.h>

#include <cstdlib>

#include "core/error.h"

namespace raygate::cli {

namespace {

const CLI::App& root_of(const CLI::App& command) {
  const CLI::App* app = &command;
  while (app->get_parent() != nullptr) app = app->get_parent();
  return *app;
}

void deprecation_note(const std::string& old_name, const std::string& current) {
  fmt::print(stderr, "raygate: note: {} is deprecated; use {}\n", old_name, current);
}

}  // namespace

void add_global_options(CLI::App& app) {
  app.add_option("--color", "colour: auto (a terminal, unless NO_COLOR is set), always, never")
      ->check(CLI::IsMember({"auto", "always", "never"}))
      ->default_str("auto");
  const std::string quiet_help = "say nothing but warnings, errors and the results asked for";
  app.add_flag("-q,--quiet", quiet_help);
  // Read before parsing (cli/project_config.h); declared here for --help and to be accepted.
  app.add_option("--config",
                 "project config file (default: ./raygate.toml when it exists; docs/cli.md)");
  app.fallthrough();  // `raygate run --quiet ...` as well as `raygate --quiet run ...`
}

Console console_of(const CLI::App& command) {
  const CLI::App& root = root_of(command);
  const CLI::Option* colour = root.get_option_no_throw("--color");
  const CLI::Option* quiet = root.get_option_no_throw("--quiet");
  const ColourChoice choice = colour != nullptr && colour->count() > 0
                                  ? parse_colour_choice(colour->as<std::string>())
                                  : ColourChoice::automatic;
  return Console(choice, quiet != nullptr && quiet->count() > 0, std::getenv("NO_COLOR"));
}

CLI::Option* add_deprecated_alias(CLI::App& command, const std::string& old_name,
                                  CLI::Option* current, std::string& variable) {
  const std::string current_name = "--" + current->get_lnames().front();
  CLI::Option* alias = command.add_option(old_name, variable, "deprecated: use " + current_name);
  alias->group("Deprecated")->excludes(current)->each([old_name, current_name](const std::string&) {
    deprecation_note(old_name, current_name);
  });
  return alias;
}

CLI::Option* add_format_option(CLI::App& command, std::string& format,
                               const std::vector<std::string>& formats, bool json_alias) {
  format = formats.front();
  std::string names;
  for (const std::string& f : formats) names += (names.empty() ? "" : ", ") + f;
  const std::string help = "what to print on standard output: " + names;
  CLI::Option* option = command.add_option("--format", format, help)
                            ->check(CLI::IsMember(formats))
                            ->capture_default_str();
  if (json_alias) {
    const auto as_json = [&format] {
      deprecation_note("--json", "--format json");
      format = "json";
    };
    command.add_flag_callback("--json", as_json, "deprecated: use --format json")
        ->group("Deprecated")
        ->excludes(option);
  }
  return option;
}

}  // namespace raygate::cli

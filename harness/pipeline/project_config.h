// The project's own defaults for the options every command would otherwise repeat: --repo,
// --adapter, --suite, --policy and --store, from RAYGATE_* environment variables and a project
// config file (docs/cli.md). Precedence: the command line, then the environment, then the file,
// then raygate's built-in defaults. The file is ./raygate.toml when it exists, or the one named
// by --config FILE or RAYGATE_CONFIG; TOML or INI key = value lines, read by CLI11's parser.
// This is the reading; cli/project_config.h puts the values into the options.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace raygate {

inline constexpr const char* kProjectConfigFile = "raygate.toml";

struct ProjectValue {
  std::string value;
  std::string origin;  // "RAYGATE_ADAPTER", "/path/raygate.toml:3"
};

// Key ("repo", "adapter", "suite", "policy", "store") -> value and where it came from.
using ProjectDefaults = std::map<std::string, ProjectValue>;

// The keys, in the order docs/cli.md lists them, and each one's environment variable.
const std::vector<std::string>& project_keys();
std::string environment_name(const std::string& key);

// Reads a config file. Paths in it (repo, policy, store; adapter and suite when such a file
// exists beside it) are relative to the file's folder; URLs stay as they are. UsageError, with
// file and line, for an unknown key, a section, a list, or a file that is not key = value.
ProjectDefaults read_project_config(const std::filesystem::path& file);

// The defaults in effect: `config_argument` (--config, "" when not given), else RAYGATE_CONFIG,
// else ./raygate.toml when it exists; then the environment over it. `getenv` is injectable
// for tests.
ProjectDefaults load_project_defaults(
    const std::string& config_argument, const std::function<const char*(const char*)>& getenv =
                                            [](const char* name) { return std::getenv(name); });

// The value of --config FILE / --config=FILE among the arguments, "" when absent: it must be
// known before parsing, because the defaults it holds are put into the options parsed.
std::string find_config_argument(int argc, const char* const* argv);

}  // namespace raygate

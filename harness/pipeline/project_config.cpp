#include "pipeline/project_config.h"

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include <algorithm>
#include <sstream>
#include <string_view>
#include <system_error>

#include "core/error.h"
#include "core/fs.h"

namespace raygate {

namespace {

bool is_url(const std::string& value) {
  return value.find("://") != std::string::npos || value.rfind("git@", 0) == 0;
}

// The line of `file` where `key` is set, for messages ("" when not found).
// ":N", the line where `key` is given the `occurrence`th time; "" when it is not.
std::string line_of(const std::string& text, const std::string& key, int occurrence = 1) {
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    const auto start = line.find_first_not_of(" \t");
    const auto after = start == std::string::npos ? start : start + key.size();
    const bool is_key = start != std::string::npos && line.compare(start, key.size(), key) == 0 &&
                        (after >= line.size() ||
                         std::string_view(" \t=").find(line[after]) != std::string_view::npos);
    if (is_key && --occurrence == 0) {
      return ":" + std::to_string(number);
    }
  }
  return "";
}

std::string resolve(const std::string& key, const std::string& value,
                    const std::filesystem::path& folder) {
  if (value.empty() || is_url(value) || std::filesystem::path(value).is_absolute()) return value;
  std::filesystem::path beside = (folder / value).lexically_normal();
  if (!beside.has_filename()) beside = beside.parent_path();  // "dir/.." is "/tmp/", not "/tmp"
  if (key == "adapter" || key == "suite") {  // the name of a shipped one, or a file (not a folder)
    std::error_code ec;  // one that cannot be followed is not a file here: the name stands
    return std::filesystem::is_regular_file(beside, ec) ? beside.string() : value;
  }
  return beside.string();
}

// Whether `file` is a config file to read. A path the system cannot follow (a symlink loop, a
// folder without permission) is the user's to fix: said with its reason and who named it, not
// left to escape as an internal error.
bool is_config_file(const std::filesystem::path& file, const std::string& named_by) {
  std::error_code ec;
  const bool regular = std::filesystem::is_regular_file(file, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) {
    throw UsageError(fmt::format("{}{}: cannot read: {}", named_by, file.string(), ec.message()));
  }
  return regular;
}

// A file named by --config or RAYGATE_CONFIG must be one; a folder is said to be a folder.
void require_config_file(const std::filesystem::path& file, const std::string& named_by) {
  if (is_config_file(file, named_by)) return;
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(file, ec);
  // /dev/zero is there: "no such file" sent the user looking for a file that exists.
  const char* what = std::filesystem::is_directory(status) ? "is a directory, not a config file"
                     : std::filesystem::exists(status)
                         ? "is not a regular file (a device, FIFO or socket), not a config file"
                         : "no such file";
  throw UsageError(fmt::format("{}{}: {}", named_by, file.string(), what));
}

// ./raygate.toml is read when it exists: one that exists and is no file (a folder, a FIFO) would
// leave the project's defaults out without a word.
void refuse_default_config_of_another_kind() {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(kProjectConfigFile, ec);
  if (!std::filesystem::exists(status)) return;
  throw UsageError(fmt::format(
      "./{} is {}, not a config file (raygate reads ./{} when it exists): rename it, or give "
      "--config FILE",
      kProjectConfigFile, std::filesystem::is_directory(status) ? "a directory" : "not a file",
      kProjectConfigFile));
}

// A line as shown in a message: from its first character, without trailing blanks.
std::string trimmed_line(const std::string& line, std::size_t start) {
  return line.substr(start, line.find_last_not_of(" \t\r") + 1 - start);
}

// What CLI11's reader lets through: a quoted value that never closes (the quote would become
// part of a path), a key with nothing after its `=` (the built-in default would be used
// without a word) and a section, even one with no key after it. Each is refused at its file:line:column.
void check_values(const std::string& text, const std::filesystem::path& file) {
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    // CLI11 ends a value at a NUL byte: `store = "a<NUL>b.db"` was the store `a`.
    if (const std::size_t nul = line.find('\0'); nul != std::string::npos) {
      throw UsageError(fmt::format("{}:{}:{}: a NUL byte; a config file is text", file.string(),
                                   number, nul + 1));
    }
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos || line[start] == '#' || line[start] == ';') continue;
    if (line[start] == '[') {  // with no key after it, CLI11 read a section as nothing
      throw UsageError(
          fmt::format("{}:{}:{}: {}: sections are not read; write the keys at the "
                      "top of the file",
                      file.string(), number, start + 1, trimmed_line(line, start)));
    }
    const std::size_t equals = line.find('=');
    if (equals == std::string::npos) {  // not echoed: the value may be a store URL's password
      throw UsageError(fmt::format("{}:{}:{}: no '=' on this line; write key = \"value\"",
                                   file.string(), number, start + 1));
    }
    if (equals <= start) continue;  // CLI11 says what is wrong
    const std::size_t value = line.find_first_not_of(" \t\r", equals + 1);
    const std::string key =
        line.substr(start, line.find_last_not_of(" \t", equals - 1) + 1 - start);
    if (value == std::string::npos) {
      throw UsageError(fmt::format("{}:{}: {} has no value; give one, or remove the line",
                                   file.string(), number, key));
    }
    if (line[value] == '[') {  // CLI11 reads ["a"] as the value a: a list is not one value
      throw UsageError(fmt::format("{}:{}:{}: {} is a list; give one value", file.string(), number,
                                   value + 1, key));
    }
    const char quote = line[value];
    if ((quote == '"' || quote == '\'') && line.find(quote, value + 1) == std::string::npos) {
      throw UsageError(
          fmt::format("{}:{}:{}: unterminated string: {} opens with {} and never "
                      "closes it",
                      file.string(), number, value + 1, key, quote));
    }
  }
}

}  // namespace

const std::vector<std::string>& project_keys() {
  static const std::vector<std::string> keys{"repo", "adapter", "suite", "policy", "store"};
  return keys;
}

std::string environment_name(const std::string& key) {
  std::string name = "RAYGATE_" + key;
  std::transform(name.begin(), name.end(), name.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return name;
}

ProjectDefaults read_project_config(const std::filesystem::path& file) {
  const std::filesystem::path absolute = std::filesystem::absolute(file);
  std::string text = read_file(absolute);
  // A byte-order mark (some Windows editors write one) is read past, as the JSON files' is: it
  // made the first key "\xEF\xBB\xBFrepo", an unknown key whose name looked right.
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);
  check_values(text, absolute);
  std::istringstream stream(text);
  std::vector<CLI::ConfigItem> items;
  try {
    items = CLI::ConfigTOML().from_config(stream);
  } catch (const CLI::Error& e) {
    throw UsageError(fmt::format("{}: not a config file: {}", absolute.string(), e.what()));
  }
  ProjectDefaults defaults;
  for (const CLI::ConfigItem& item : items) {
    const std::string where = absolute.string() + line_of(text, item.name);
    if (item.name == "++" || item.name == "--") continue;  // CLI11's section markers
    if (!item.parents.empty()) {
      throw UsageError(
          fmt::format("{}: [{}] {}: sections are not read; write the keys at the "
                      "top of the file",
                      where, item.parents.front(), item.name));
    }
    const auto& keys = project_keys();
    if (std::find(keys.begin(), keys.end(), item.name) == keys.end()) {
      throw UsageError(
          fmt::format("{}: unknown key '{}'; the keys are repo, adapter, suite, "
                      "policy and store",
                      where, item.name));
    }
    // CLI11 joins a key given twice into one with two values: the second line is the mistake.
    if (const std::string again = line_of(text, item.name, 2); !again.empty()) {
      throw UsageError(fmt::format("{}{}: {} is given again (first at line {}); give it once",
                                   absolute.string(), again, item.name,
                                   where.substr(where.rfind(':') + 1)));
    }
    if (item.inputs.size() != 1) {
      throw UsageError(fmt::format("{}: {}: expected one value", where, item.name));
    }
    defaults[item.name] = {resolve(item.name, item.inputs.front(), absolute.parent_path()), where};
  }
  return defaults;
}

ProjectDefaults load_project_defaults(const std::string& config_argument,
                                      const std::function<const char*(const char*)>& getenv) {
  ProjectDefaults defaults;
  const char* from_env = getenv("RAYGATE_CONFIG");
  if (!config_argument.empty()) {
    require_config_file(config_argument, "--config ");
    defaults = read_project_config(config_argument);
  } else if (from_env != nullptr && *from_env != '\0') {
    require_config_file(from_env, "RAYGATE_CONFIG=");
    defaults = read_project_config(from_env);
  } else if (is_config_file(kProjectConfigFile, "")) {
    defaults = read_project_config(kProjectConfigFile);
  } else {
    refuse_default_config_of_another_kind();
  }
  for (const std::string& key : project_keys()) {
    const std::string name = environment_name(key);
    const char* value = getenv(name.c_str());
    if (value != nullptr && *value != '\0') defaults[key] = {value, name};
  }
  return defaults;
}

std::string find_config_argument(int argc, const char* const* argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;
    if (arg == "--config" && i + 1 < argc) return argv[i + 1];
    if (arg.rfind("--config=", 0) == 0) return arg.substr(9);
  }
  return "";
}

}  // namespace raygate

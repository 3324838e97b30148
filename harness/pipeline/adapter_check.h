// `raygate adapter check` as a library call: one adapter file read and validated, what raygate
// will run with it (pipeline/adapter_summary.h), and whether the Debian packages it requires
// are installed. A front end prints what comes back; nothing here prints.
#pragma once

#include <filesystem>
#include <string>

namespace raygate {

// The one lookup of --adapter and `adapter check` (issue 40: check refused "blender-cycles",
// which compare accepted): a file path as given, else a shipped adapter of that name
// (<data_root>/adapters/NAME.json). UsageError naming both when neither exists.
std::filesystem::path find_adapter(const std::string& name_or_path,
                                   const std::filesystem::path& data_root);

struct AdapterCheck {
  std::string error;    // why the file is not a valid adapter; "" when it is
  std::string summary;  // a valid adapter read back, "FILE: ok" and one line per field
  // "" or a warning (lines after the first indented): packages its "requires" names that are
  // not installed, with the apt-get line, or why that could not be checked (not Debian). Only
  // a warning: the build may still find its tools.
  std::string warning;
};

// Never throws a UsageError for the file: an invalid adapter is the `error` of its check, so a
// front end can go on to the next file and report every problem, not just the first file's.
// `file` is a path or a shipped adapter's name (find_adapter, in raygate's own data root).
AdapterCheck check_adapter_file(const std::string& file);

}  // namespace raygate

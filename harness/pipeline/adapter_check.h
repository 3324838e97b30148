// `raygate adapter check` as a library call: one adapter file read and validated, what raygate
// will run with it (pipeline/adapter_summary.h), and whether the Debian packages it requires
// are installed. A front end prints what comes back; nothing here prints.
#pragma once

#include <string>

namespace raygate {

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
AdapterCheck check_adapter_file(const std::string& file);

}  // namespace raygate

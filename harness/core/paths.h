// Where raygate finds its own data (suites, goldens) and its sibling tools (raygate-baseline).
// Installed layout: <prefix>/bin/raygate, <prefix>/share/raygate/{scenes,golden}. Build tree:
// both binaries in <build>/bin, data in the source tree. RAYGATE_HOME overrides the data root.
#pragma once

#include <filesystem>

namespace raygate {

struct ToolPaths {
  std::filesystem::path data_root;  // holds scenes/suites/ and golden/
  std::filesystem::path baseline;   // the raygate-baseline executable
};

// Resolved from the running executable; `baseline_override`, if set, wins for the baseline.
// A UsageError first when the working directory, TMPDIR or RAYGATE_HOME is not UTF-8 text: the
// paths made from them go into JSON.
ToolPaths locate_tools(const std::filesystem::path& baseline_override = {});

// The directory of the running executable (/proc/self/exe).
std::filesystem::path executable_directory();

}  // namespace raygate

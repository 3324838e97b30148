#include "core/paths.h"

#include <unistd.h>

#include <cstdlib>

#include "core/error.h"

#ifndef RAYGATE_SOURCE_DIR
#error "RAYGATE_SOURCE_DIR must be defined by the build"
#endif

namespace raygate {

std::filesystem::path executable_directory() {
  std::error_code ec;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw InfraError("cannot locate the raygate executable: " + ec.message());
  return self.parent_path();
}

ToolPaths locate_tools(const std::filesystem::path& baseline_override) {
  ToolPaths paths;
  const std::filesystem::path bin = executable_directory();
  if (const char* home = std::getenv("RAYGATE_HOME"); home != nullptr && *home != '\0') {
    paths.data_root = home;
  } else if (std::filesystem::exists(bin.parent_path() / "share/raygate/scenes/suites")) {
    paths.data_root = bin.parent_path() / "share/raygate";
  } else {
    paths.data_root = RAYGATE_SOURCE_DIR;
  }
  if (!baseline_override.empty()) {
    // The user named it: one that is not there is a usage error (exit 2), not a broken install.
    // Absolute: the baseline runs in each run's own folder, where `./raygate-baseline` is not.
    std::error_code ec;
    paths.baseline = std::filesystem::absolute(baseline_override, ec);
    if (!std::filesystem::is_regular_file(paths.baseline, ec) ||
        ::access(paths.baseline.c_str(), X_OK) != 0) {
      throw UsageError("--baseline " + baseline_override.string() +
                       ": not an executable file (give the path of a raygate-baseline)");
    }
    return paths;
  }
  paths.baseline = bin / "raygate-baseline";
  if (!std::filesystem::exists(paths.baseline)) {
    throw InfraError("raygate-baseline not found at " + paths.baseline.string() +
                     " (build it, or pass --baseline PATH)");
  }
  return paths;
}

}  // namespace raygate

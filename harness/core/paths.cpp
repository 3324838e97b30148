#include "core/paths.h"

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
  paths.baseline = baseline_override.empty() ? bin / "raygate-baseline" : baseline_override;
  if (!std::filesystem::exists(paths.baseline)) {
    throw InfraError("raygate-baseline not found at " + paths.baseline.string() +
                     " (build it, or pass --baseline PATH)");
  }
  return paths;
}

}  // namespace raygate

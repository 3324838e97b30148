#include "core/paths.h"

#include <unistd.h>

#include <cstdlib>

#include "core/error.h"
#include "core/utf8.h"

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

namespace {

// Every command that builds, renders or measures finds its tools here, before the work: paths
// raygate makes from the working directory, TMPDIR and RAYGATE_HOME go into JSON (documents,
// the baseline's stats), which holds only text. From a folder named in Latin-1 the baseline
// aborted on every render and `golden bless` ended in an internal error (sweep 13).
void refuse_folders_that_are_not_text() {
  std::error_code error;
  const std::string cwd = std::filesystem::current_path(error).string();
  if (!error && !is_valid_utf8(cwd)) {
    throw UsageError("the working directory, " + repaired_utf8(cwd) +
                     ", is not UTF-8 text: raygate writes the paths it makes into JSON, which "
                     "holds only text; run it from a folder whose path is");
  }
  for (const char* name : {"TMPDIR", "RAYGATE_HOME"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && !is_valid_utf8(value)) {
      throw UsageError(std::string(name) + "=" + repaired_utf8(value) +
                       " is not UTF-8 text: raygate writes the paths it makes into JSON, which "
                       "holds only text; name a folder whose path is");
    }
  }
}

}  // namespace

ToolPaths locate_tools(const std::filesystem::path& baseline_override) {
  refuse_folders_that_are_not_text();
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

#include "compare/run_folder.h"

#include <fmt/core.h>

namespace raygate {

std::optional<std::string> vanished_run_folder(const std::filesystem::path& actual) {
  std::error_code ec;
  if (actual.empty() || std::filesystem::exists(actual, ec) ||
      std::filesystem::exists(actual.parent_path(), ec)) {
    return std::nullopt;
  }
  return fmt::format(
      "{}: the run's folder is gone (deleted while raygate ran?), so its image "
      "could not be checked",
      actual.parent_path().string());
}

}  // namespace raygate

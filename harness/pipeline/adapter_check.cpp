#include "pipeline/adapter_check.h"

#include <fmt/core.h>

#include <vector>

#include "adapter/adapter.h"
#include "adapter/packages.h"
#include "core/error.h"
#include "core/paths.h"
#include "pipeline/adapter_summary.h"

namespace raygate {
namespace {

std::string packages_warning(const Adapter& adapter) {
  try {
    const std::vector<std::string> missing = missing_packages(adapter);
    if (missing.empty()) return {};
    std::string list;
    for (const std::string& p : missing) list += (list.empty() ? "" : ", ") + p;
    return fmt::format("{}: Debian packages not installed: {}\n  install them with: {}",
                       adapter.file.string(), list, apt_get_line(missing));
  } catch (const InfraError& e) {
    return fmt::format("{}: cannot check \"requires\": {}", adapter.file.string(), e.what());
  }
}

}  // namespace

std::filesystem::path find_adapter(const std::string& name,
                                   const std::filesystem::path& data_root) {
  const std::filesystem::path direct(name);
  if (std::filesystem::exists(direct)) return direct;
  const std::filesystem::path shipped = data_root / "adapters" / (name + ".json");
  if (name.find('/') == std::string::npos && std::filesystem::exists(shipped)) return shipped;
  throw UsageError(
      fmt::format("adapter '{}' not found: not a file, and not a shipped adapter "
                  "(see {}/adapters/)",
                  name, data_root.string()));
}

AdapterCheck check_adapter_file(const std::string& file) {
  AdapterCheck check;
  try {
    const Adapter adapter = load_adapter(find_adapter(file, locate_tools().data_root));
    check.summary = adapter_summary(adapter);
    check.warning = packages_warning(adapter);
  } catch (const UsageError& e) {
    check.error = e.what();
  }
  return check;
}

}  // namespace raygate

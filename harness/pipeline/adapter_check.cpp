#include "pipeline/adapter_check.h"

#include <fmt/core.h>

#include <vector>

#include "adapter/adapter.h"
#include "adapter/packages.h"
#include "core/error.h"
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

AdapterCheck check_adapter_file(const std::string& file) {
  AdapterCheck check;
  try {
    const Adapter adapter = load_adapter(file);
    check.summary = adapter_summary(adapter);
    check.warning = packages_warning(adapter);
  } catch (const UsageError& e) {
    check.error = e.what();
  }
  return check;
}

}  // namespace raygate

#include "adapter/packages.h"

#include "core/error.h"
#include "core/fs.h"
#include "core/process.h"

namespace raygate {
namespace {

// dpkg-query exits 1 for a package it has never heard of, and 0 with a status such as
// "deinstall ok config-files" for one that was removed. "<want> ok installed" means the files
// are there; a package installed for two architectures prints two statuses back to back.
bool installed(const std::string& package, const TempDir& scratch) {
  ProcessSpec spec;
  spec.argv = {"dpkg-query", "-W", "-f=${Status}", package};
  spec.stdout_path = scratch.path() / "status.txt";
  spec.timeout = std::chrono::seconds(30);
  const ProcessResult result = run_process(spec);
  if (result.outcome == ProcessOutcome::spawn_failed) {
    throw InfraError("cannot ask dpkg which packages are installed: " + result.spawn_error);
  }
  if (!result.succeeded()) return false;
  return read_file(spec.stdout_path).find(" ok installed") != std::string::npos;
}

}  // namespace

std::vector<std::string> missing_packages(const Adapter& adapter) {
  std::vector<std::string> missing;
  if (adapter.packages.empty()) return missing;
  const TempDir scratch("raygate-dpkg");
  for (const std::string& package : adapter.packages) {
    if (!installed(package, scratch)) missing.push_back(package);
  }
  return missing;
}

std::string apt_get_line(const std::vector<std::string>& packages) {
  if (packages.empty()) return "";
  std::string line = "apt-get install -y";
  for (const std::string& p : packages) line += " " + p;
  return line;
}

}  // namespace raygate

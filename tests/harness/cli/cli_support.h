// Running the built raygate binary from tests: exit code and captured output.
#pragma once

#include <string>
#include <vector>

#include "core/fs.h"
#include "core/process.h"

namespace raygate::test {

struct CliRun {
  int exit_code = -1;
  std::string out;  // stdout and stderr merged
};

inline CliRun run_raygate(const std::vector<std::string>& args, const TempDir& dir) {
  ProcessSpec spec;
  spec.argv = {RAYGATE_EXE};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.stdout_path = dir.path() / "cli.log";
  spec.stderr_path = spec.stdout_path;
  spec.working_directory = dir.path();
  spec.timeout = std::chrono::minutes(5);
  const ProcessResult r = run_process(spec);
  return {r.outcome == ProcessOutcome::exited ? r.exit_code : -1, read_file(spec.stdout_path)};
}

}  // namespace raygate::test

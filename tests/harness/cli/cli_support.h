// Running the built raygate binary from tests: exit code and captured output.
#pragma once

#include <chrono>
#include <map>
#include <string>
#include <vector>

#include "core/fs.h"
#include "core/process.h"

// Sanitizer builds run raygate 3-10 times slower (cmake/RaygateTesting.cmake sets the factor):
// a run's time limit guards against a hang, so it grows with them.
#ifndef RAYGATE_TEST_TIME_SCALE
#define RAYGATE_TEST_TIME_SCALE 1
#endif

namespace raygate::test {

inline constexpr std::chrono::minutes kCliTimeout{5 * RAYGATE_TEST_TIME_SCALE};

struct CliRun {
  int exit_code = -1;
  std::string out;  // stdout and stderr merged
};

// raygate with `args` in `dir`, standard output and error merged into <dir>/cli.log.
inline ProcessSpec raygate_spec(const std::vector<std::string>& args, const TempDir& dir,
                                std::chrono::minutes timeout = kCliTimeout) {
  ProcessSpec spec;
  spec.argv = {RAYGATE_EXE};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.stdout_path = dir.path() / "cli.log";
  spec.stderr_path = spec.stdout_path;
  spec.working_directory = dir.path();
  spec.timeout = timeout;
  return spec;
}

inline CliRun run_raygate(const std::vector<std::string>& args, const TempDir& dir) {
  const ProcessSpec spec = raygate_spec(args, dir);
  const ProcessResult r = run_process(spec);
  return {r.outcome == ProcessOutcome::exited ? r.exit_code : -1, read_file(spec.stdout_path)};
}

// Standard output and standard error apart, for what a command promises about each; `env` is
// set on top of the test's environment.
struct CliStreams {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline CliStreams run_raygate_streams(const std::vector<std::string>& args, const TempDir& dir,
                                      const std::map<std::string, std::string>& env = {}) {
  ProcessSpec spec;
  spec.argv = {RAYGATE_EXE};
  spec.argv.insert(spec.argv.end(), args.begin(), args.end());
  spec.environment = env;
  spec.stdout_path = dir.path() / "cli.out";
  spec.stderr_path = dir.path() / "cli.err";
  spec.working_directory = dir.path();
  spec.timeout = kCliTimeout;
  const ProcessResult r = run_process(spec);
  return {r.outcome == ProcessOutcome::exited ? r.exit_code : -1, read_file(spec.stdout_path),
          read_file(spec.stderr_path)};
}

}  // namespace raygate::test

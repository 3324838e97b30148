// Running an adapter's build steps for one build: in order, without a shell, in {src}, each
// step's output in its own log, all of them inside the adapter's one build timeout, stopping at
// the first step that does not succeed (the build's exit status always wins; adapters/README.md).
#pragma once

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "builder/build_record.h"

namespace raygate {

struct StepSettings {
  std::filesystem::path working_directory;         // {src}
  std::filesystem::path logs_dir;                  // step-N.log go here, N from 1
  std::chrono::steady_clock::time_point deadline;  // the whole build's
  double timeout_seconds = 0.0;                    // the same, for messages
};

struct StepsResult {
  std::vector<BuildStepRecord> steps;  // those that ran; the last one failed if !success
  bool success = false;
  std::string failure;   // "step 2 of 3 `make -j 4` exited with status 2"
  std::string log_tail;  // last lines of the failed step's log
};

// Runs the already expanded steps. Never throws for a step that fails, crashes, hangs or cannot
// start: that is a failed build. Throws InfraError only if a log cannot be created.
StepsResult run_build_steps(const std::vector<std::vector<std::string>>& steps,
                            const StepSettings& settings);

// argv as one could paste it into a shell, for messages: `cmake -S '/my src' -B /b`.
std::string argv_text(const std::vector<std::string>& argv);

// How many lines of a failed step's log a failure shows.
constexpr int kFailureLogLines = 20;

}  // namespace raygate

#include "runner/executor.h"

#include <chrono>

namespace raygate {

ProcessResult SystemExecutor::run(const ProcessSpec& spec) { return run_process(spec); }

std::vector<ProcessResult> SystemExecutor::run_together(const std::vector<ProcessSpec>& specs) {
  std::vector<Process> running;
  running.reserve(specs.size());
  for (const ProcessSpec& spec : specs) running.push_back(Process::start(spec));
  std::vector<ProcessResult> results;
  results.reserve(running.size());
  for (Process& process : running) results.push_back(process.wait());
  return results;
}

double SteadyClock::now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace raygate

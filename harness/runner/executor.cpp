#include "runner/executor.h"

#include <chrono>
#include <exception>
#include <thread>

namespace raygate {

ProcessResult SystemExecutor::run(const ProcessSpec& spec) { return run_process(spec); }

std::vector<ProcessResult> SystemExecutor::run_together(const std::vector<ProcessSpec>& specs) {
  std::vector<Process> running;
  running.reserve(specs.size());
  for (const ProcessSpec& spec : specs) running.push_back(Process::start(spec));
  // Each process is waited for in its own thread. Waiting for them one after the other would
  // reap (and so time) a process that ended first only when the one before it in the list
  // ends, and leave its output pipe undrained meanwhile, blocking a chatty tracer.
  std::vector<ProcessResult> results(running.size());
  std::vector<std::exception_ptr> errors(running.size());
  std::vector<std::thread> waiters;
  for (std::size_t i = 0; i < running.size(); ++i) {
    waiters.emplace_back([&, i] {
      try {
        results[i] = running[i].wait();
      } catch (...) {
        errors[i] = std::current_exception();
      }
    });
  }
  for (std::thread& waiter : waiters) waiter.join();
  for (const std::exception_ptr& error : errors) {
    if (error) std::rethrow_exception(error);
  }
  return results;
}

double SteadyClock::now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace raygate

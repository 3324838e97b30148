// The two things the scheduler needs from the world: a way to run processes (one at a time, or
// several at once for the duet schedule) and a clock. Behind interfaces so the scheduler's unit
// tests drive it with a fake process table and a fake clock: fast, exact, no timing in tests.
#pragma once

#include <vector>

#include "core/process.h"

namespace raygate {

class Executor {
 public:
  virtual ~Executor() = default;
  virtual ProcessResult run(const ProcessSpec& spec) = 0;
  // Starts every spec before waiting for any, so they run at the same time.
  virtual std::vector<ProcessResult> run_together(const std::vector<ProcessSpec>& specs) = 0;
};

// Real child processes (core/process.h).
class SystemExecutor final : public Executor {
 public:
  ProcessResult run(const ProcessSpec& spec) override;
  std::vector<ProcessResult> run_together(const std::vector<ProcessSpec>& specs) override;
};

class Clock {
 public:
  virtual ~Clock() = default;
  virtual double now_seconds() = 0;  // monotonic; only differences mean anything
};

class SteadyClock final : public Clock {
 public:
  double now_seconds() override;
};

}  // namespace raygate

// A fake process table and a fake clock (runner/executor.h) for the tests of the scheduler and
// of the pipeline: runs take scripted wall seconds and advance the clock by them, so those
// tests are exact and take no time.
#pragma once

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "runner/executor.h"

namespace raygate::testing {

// Time stands still unless a fake process runs.
class FakeClock final : public Clock {
 public:
  double now_seconds() override { return now_; }
  void advance(double seconds) { now_ += seconds; }

 private:
  double now_ = 1000.0;
};

// One process the fake executor was asked to run.
struct Call {
  std::string role;           // argv[0]
  std::vector<int> cpus;      // its cpu_affinity
  int batch = 0;              // executor call it came in; specs of one run_together share it
  std::filesystem::path log;  // its stdout_path, which names the run directory
};

inline ProcessResult exited_with(int code, double wall_seconds) {
  ProcessResult result;
  result.outcome = ProcessOutcome::exited;
  result.exit_code = code;
  result.wall_seconds = wall_seconds;
  result.user_seconds = wall_seconds * 0.75;
  result.system_seconds = wall_seconds * 0.25;
  return result;
}

inline ProcessResult killed_by(int signal) {
  ProcessResult result;
  result.outcome = ProcessOutcome::signaled;
  result.signal = signal;
  result.wall_seconds = 0.5;
  return result;
}

// A process table keyed by argv[0] (the fake contenders put their role there): every run of a
// role succeeds in its scripted wall seconds (cycled), except runs scripted to end otherwise.
// Each run advances the clock by its wall time; a run_together by the longest of its runs.
class FakeExecutor final : public Executor {
 public:
  explicit FakeExecutor(FakeClock& clock) : clock_(clock) {}

  void set_seconds(const std::string& role, std::vector<double> seconds) {
    seconds_[role] = std::move(seconds);
  }
  // The nth (1-based) run of `role` ends with `result`.
  void script(const std::string& role, int nth, ProcessResult result) {
    scripted_[{role, nth}] = std::move(result);
  }
  // Wall seconds of a run decided from its whole spec (before set_seconds is asked); nullopt
  // falls back to set_seconds.
  void time_by(std::function<std::optional<double>(const ProcessSpec&)> seconds_of) {
    seconds_of_ = std::move(seconds_of);
  }
  // What a successful run leaves behind (its image, a stats file): done by `effect`.
  void on_success(std::function<void(const ProcessSpec&)> effect) {
    on_success_ = std::move(effect);
  }

  ProcessResult run(const ProcessSpec& spec) override {
    ProcessResult result = next(spec, batches_++);
    clock_.advance(result.wall_seconds);
    return result;
  }

  std::vector<ProcessResult> run_together(const std::vector<ProcessSpec>& specs) override {
    const int batch = batches_++;
    std::vector<ProcessResult> results;
    double longest = 0.0;
    for (const ProcessSpec& spec : specs) {
      results.push_back(next(spec, batch));
      longest = std::max(longest, results.back().wall_seconds);
    }
    clock_.advance(longest);
    return results;
  }

  const std::vector<Call>& calls() const { return calls_; }
  std::vector<std::string> roles() const {
    std::vector<std::string> out;
    for (const Call& call : calls_) out.push_back(call.role);
    return out;
  }

 private:
  ProcessResult next(const ProcessSpec& spec, int batch) {
    const std::string& role = spec.argv.at(0);
    const int nth = ++runs_[role];
    calls_.push_back({role, spec.cpu_affinity, batch, spec.stdout_path});
    if (const auto found = scripted_.find({role, nth}); found != scripted_.end()) {
      return found->second;
    }
    double wall = 1.0;
    if (const std::optional<double> timed = seconds_of_ ? seconds_of_(spec) : std::nullopt) {
      wall = *timed;
    } else if (const std::vector<double>& seconds = seconds_[role]; !seconds.empty()) {
      wall = seconds[static_cast<std::size_t>(nth - 1) % seconds.size()];
    }
    if (on_success_) on_success_(spec);
    return exited_with(0, wall);
  }

  FakeClock& clock_;
  std::function<std::optional<double>(const ProcessSpec&)> seconds_of_;
  std::function<void(const ProcessSpec&)> on_success_;
  std::map<std::string, std::vector<double>> seconds_;
  std::map<std::pair<std::string, int>, ProcessResult> scripted_;
  std::map<std::string, int> runs_;
  std::vector<Call> calls_;
  int batches_ = 0;
};

}  // namespace raygate::testing

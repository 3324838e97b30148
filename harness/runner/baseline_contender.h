// raygate-baseline as a contender: the normalizer of every ratio. Timed by the same clock as the
// tracer it normalizes (DESIGN.md §11): process wall against process wall, process CPU against
// process CPU, and its in-process seconds (parse + prepare + render, from --stats) against a
// tracer that reports its own time. The in-process seconds are kept in every run record either
// way. During measurement it writes PPM, the cheapest format, and starts in milliseconds: it
// links no image library (baseline/image/encoders.h).
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "runner/baseline_cost_cache.h"
#include "runner/cachegrind.h"
#include "runner/contender.h"

namespace raygate {

// Which of the baseline's times the ratio divides by.
enum class BaselineClock {
  process_wall,  // wall seconds of the whole process (fork to wait4)
  process_cpu,   // user + system CPU seconds of the whole process (wait4's rusage)
  in_process,    // parse + prepare + render wall seconds, measured inside the process
  simulated,     // estimated cycles under cachegrind (--timing sim), like the tracer's
};

// --timing sim: the simulator, and where the baseline's costs are cached (per
// BaselineCostKey; source_sha256 is the baseline's). A null cache simulates every run.
struct BaselineSimulation {
  Cachegrind cachegrind;
  std::shared_ptr<BaselineCostCache> cache;
  std::string source_sha256;
};

// "process-wall", "process-cpu", "in-process", "simulated-cycles": the names results documents carry
// (BaselineRecord::timing). Documents written before the clocks were matched say "in-process"
// (or "in-process-cpu", against CPU-timed tracers).
std::string_view to_string(BaselineClock clock);

// The clock of a tracer timed by `source` and `metric`: "process-wall", "process-cpu" or
// "reported" (settings.tracer_clock in results documents).
std::string_view tracer_clock_name(TimingSource source, TimingMetric metric);

// The baseline clock that matches it: the process clock of the same metric, or the in-process
// seconds for a tracer that reports its own time (it does not count its start-up either).
BaselineClock matching_baseline_clock(TimingSource source, TimingMetric metric);

class BaselineContender final : public Contender {
 public:
  BaselineContender(std::filesystem::path executable, std::string sampling,
                    std::chrono::milliseconds timeout = std::chrono::minutes(30),
                    std::string accel = "none", BaselineClock clock = BaselineClock::process_wall);

  ProcessSpec command(const SceneInput& scene, const std::filesystem::path& run_dir) const override;
  RunRecord interpret(const SceneInput& scene, const ProcessResult& result,
                              const ProcessSpec& spec,
                      const std::filesystem::path& run_dir) const override;

  BaselineClock clock() const { return clock_; }

  // Required before measuring with BaselineClock::simulated.
  void simulate(BaselineSimulation simulation) { simulation_ = std::move(simulation); }

  // The cached simulated cost on this scene, as a run that did not have to happen.
  std::optional<RunRecord> known_run(const SceneInput& scene) const override;

 private:
  std::filesystem::path executable_;
  std::string sampling_;
  std::chrono::milliseconds timeout_;
  std::string accel_;
  BaselineClock clock_;
  std::optional<BaselineSimulation> simulation_;

  BaselineCostKey cost_key(const SceneInput& scene) const;
};

}  // namespace raygate

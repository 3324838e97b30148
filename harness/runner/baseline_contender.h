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
#include "runner/timing/timing_mode.h"

namespace raygate {

// --timing sim: the simulator, and where the baseline's costs are cached (per
// BaselineCostKey; source_sha256 is the baseline's). A null cache simulates every run.
struct BaselineSimulation {
  Cachegrind cachegrind;
  std::shared_ptr<BaselineCostCache> cache;
  std::string source_sha256;
};

// The baseline's own limit on one run; a user's time budget may cut it shorter.
inline constexpr std::chrono::minutes kBaselineRunLimit{30};

class BaselineContender final : public Contender {
 public:
  BaselineContender(std::filesystem::path executable, std::string sampling,
                    std::chrono::milliseconds timeout = kBaselineRunLimit,
                    std::string accel = "none", const TimingMode* clock = nullptr);

  ProcessSpec command(const SceneInput& scene, const std::filesystem::path& run_dir) const override;
  RunRecord interpret(const SceneInput& scene, const ProcessResult& result, const ProcessSpec& spec,
                      const std::filesystem::path& run_dir) const override;

  // Its clock: the tracer's timing mode (DESIGN.md §11); process wall when none was given.
  const TimingMode& clock() const { return *clock_; }

  // Required before measuring with a mode under cachegrind (--timing sim).
  void simulate(BaselineSimulation simulation) { simulation_ = std::move(simulation); }

  // The cached simulated cost on this scene, as a run that did not have to happen.
  std::optional<RunRecord> known_run(const SceneInput& scene) const override;

 private:
  std::filesystem::path executable_;
  std::string sampling_;
  std::chrono::milliseconds timeout_;
  std::string accel_;
  const TimingMode* clock_;
  std::optional<BaselineSimulation> simulation_;

  BaselineCostKey cost_key(const SceneInput& scene) const;
};

}  // namespace raygate

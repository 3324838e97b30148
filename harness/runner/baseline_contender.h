// raygate-baseline as a contender: the normalizer of every ratio. Timed by its in-process
// seconds (parse + prepare + render, from --stats), not by process wall time, because its
// process start-up is dominated by loading OpenImageIO's shared libraries (DESIGN.md §11).
#pragma once

#include <chrono>
#include <filesystem>
#include <string>

#include "runner/contender.h"

namespace raygate {

class BaselineContender final : public Contender {
 public:
  BaselineContender(std::filesystem::path executable, std::string sampling,
                    std::chrono::milliseconds timeout = std::chrono::minutes(30),
                    std::string accel = "none", TimingMetric metric = TimingMetric::wall);

  ProcessSpec command(const SceneInput& scene, const std::filesystem::path& run_dir) const override;
  RunRecord interpret(const SceneInput& scene, const ProcessResult& result,
                              const ProcessSpec& spec,
                      const std::filesystem::path& run_dir) const override;

 private:
  std::filesystem::path executable_;
  std::string sampling_;
  std::chrono::milliseconds timeout_;
  std::string accel_;
  TimingMetric metric_;  // wall: parse + prepare + render seconds; cpu: their CPU seconds
};

}  // namespace raygate

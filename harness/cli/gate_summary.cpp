#include "cli/gate_summary.h"

#include <fmt/core.h>

namespace raygate::cli {

void print_gate_summary(const GateResult& gate, std::FILE* stream) {
  for (const GateOutcome outcome : {GateOutcome::fail, GateOutcome::unmeasured, GateOutcome::warn}) {
    for (const SceneGate& scene : gate.scenes) {
      if (scene.outcome != outcome) continue;
      for (const std::string& reason : scene.reasons) {
        fmt::print(stream, "{:<10} {:<10} {}\n", to_string(outcome), scene.id, reason);
      }
    }
  }
  const std::size_t failed = gate.count(GateOutcome::fail);
  const std::size_t unmeasured = gate.count(GateOutcome::unmeasured);
  const std::size_t warned = gate.count(GateOutcome::warn);
  const char* verdict = gate.exit_code == 0   ? "PASS"
                        : gate.exit_code == 1 ? "FAIL (regression)"
                                              : "COULD NOT MEASURE";
  fmt::print(stream, "gate: {}: {} scenes, {} failed, {} unmeasured, {} warnings\n", verdict,
             gate.scenes.size(), failed, unmeasured, warned);
}

}  // namespace raygate::cli

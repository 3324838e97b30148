#include "report/gate_summary.h"

#include "core/format.h"
#include "core/sanitize.h"

#include <fmt/core.h>
#include <fmt/format.h>

#include <map>
#include <vector>

namespace raygate {

namespace {

// "3 scenes, 1 failed, 0 warnings": the unmeasured count only when it is the reason or not zero,
// so "COULD NOT MEASURE" never stands beside "0 unmeasured" unexplained.
std::string counts(const GateResult& gate) {
  // `raygate scaling` judges families, not scenes: "0 scenes" read as if its fits were lost.
  if (gate.scenes.empty() && gate.problems.empty()) {
    if (gate.families.empty()) {
      return "nothing judged (a run's growth exponents are fitted; a compare's are judged)";
    }
    std::size_t failed = 0;
    for (const SceneGate& family : gate.families) failed += family.outcome == GateOutcome::fail;
    return fmt::format("{} growth exponents judged, {} failed", gate.families.size(), failed);
  }
  std::vector<std::string> parts{count_text(gate.scenes.size(), "scene"),
                                 fmt::format("{} failed", gate.count(GateOutcome::fail))};
  const std::size_t unmeasured = gate.count(GateOutcome::unmeasured);
  if (unmeasured > 0 || gate.problems.empty()) {
    parts.push_back(fmt::format("{} unmeasured", unmeasured));
  }
  parts.push_back(count_text(gate.count(GateOutcome::warn), "warning"));
  // Memory judged (issue 27): how many scenes each verdict, so a pass says memory was looked at.
  std::map<ChangeVerdict, std::size_t> memory;
  for (const SceneGate& scene : gate.scenes) {
    if (scene.memory) ++memory[*scene.memory];
  }
  if (!memory.empty()) {
    std::vector<std::string> verdicts;
    for (const auto& [verdict, n] : memory) {
      verdicts.push_back(fmt::format("{} {}", n, to_string(verdict)));
    }
    parts.push_back(fmt::format("memory: {}", fmt::join(verdicts, ", ")));
  }
  if (!gate.families.empty()) {
    parts.push_back(fmt::format("{} growth exponents judged", gate.families.size()));
  }
  return fmt::format("{}", fmt::join(parts, ", "));
}

// The scenes, then the growth exponents of scene families (gate/growth_gate.h).
std::vector<SceneGate> all_gates(const GateResult& gate) {
  std::vector<SceneGate> all = gate.scenes;
  all.insert(all.end(), gate.families.begin(), gate.families.end());
  return all;
}

}  // namespace

void print_gate_summary(const GateResult& gate, std::FILE* stream) {
  for (const GateOutcome outcome :
       {GateOutcome::fail, GateOutcome::unmeasured, GateOutcome::warn}) {
    for (const SceneGate& scene : all_gates(gate)) {
      if (scene.outcome != outcome) continue;
      for (const std::string& reason : scene.reasons) {
        fmt::print(stream, "{:<10} {:<10} {}\n", to_string(outcome), terminal_line(scene.id),
                   terminal_line(reason));
      }
    }
  }
  // A document's text (commit subjects, paths) reaches these lines: a terminal must not obey it.
  for (const std::string& note : gate.notes) fmt::print(stream, "note: {}\n", terminal_line(note));
  const char* verdict = gate.exit_code == 0   ? "PASS"
                        : gate.exit_code == 1 ? "FAIL (regression)"
                                              : "COULD NOT MEASURE";
  std::string why;
  for (const std::string& problem : gate.problems) why += "; " + problem;
  fmt::print(stream, "gate: {}: {}{}\n", verdict, counts(gate), terminal_line(why));
}

}  // namespace raygate

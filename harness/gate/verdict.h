// The gate (DESIGN.md §6-§9): a results document and a policy in, one verdict per scene and the
// exit code out. Each scene that fails gets one line that says why in numbers, so a CI log
// reader knows what broke without opening anything else.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "compare/image_verdict.h"
#include "gate/policy.h"
#include "results/results.h"

namespace raygate {

enum class GateOutcome {
  pass,        // measured; nothing wrong
  warn,        // an image over the warn threshold, an inconclusive change
  unmeasured,  // raygate could not measure it (the baseline or base failed, a run crashed): exit 3
  fail,        // slower beyond the policy, an image over the fail thresholds, or head crashing
               // where base ran: exit 1 (a found regression outranks what could not be measured)
};

// What the gate made of a scene's time: the change's verdict under the policy (compare), measured
// (a run: nothing to judge against), or failed (a run crashed, so there is no time).
enum class SpeedVerdict { measured, unchanged, improved, regressed, inconclusive, failed };

// "MEASURED", "UNCHANGED", ..., as the reports and JSON print it (the change verdicts' words).
std::string_view to_string(SpeedVerdict verdict);
SpeedVerdict speed_verdict(ChangeVerdict verdict);
// The change verdict the speed verdict is; nullopt for measured and failed.
std::optional<ChangeVerdict> change_verdict_of(SpeedVerdict verdict);

struct SceneGate {
  std::string id;
  SpeedVerdict speed = SpeedVerdict::measured;
  // The max slowdown the speed verdict was judged at (0 when no change was judged): an
  // INCONCLUSIVE scene's report names the interval that would decide it at this limit.
  double speed_limit = 0.0;
  // What the speed part (time, or a crash) and the image part say against the scene, apart, for
  // the reports' columns and JUnit; `outcome` is the worst of them and memory's.
  GateOutcome speed_outcome = GateOutcome::pass;
  std::optional<ImageVerdict> image;  // the worst image verdict; nullopt when none was checked
  GateOutcome image_outcome = GateOutcome::pass;
  // Peak memory head vs base (gate/memory_gate.h); nullopt for a run, or without own peaks.
  std::optional<ChangeVerdict> memory;
  GateOutcome outcome = GateOutcome::pass;
  std::vector<std::string> reasons;  // for anything but pass: what, in numbers
};

struct GateResult {
  std::vector<SceneGate> scenes;
  // A compare's growth exponents by scene family, "scaling:<family>" (gate/growth_gate.h).
  std::vector<SceneGate> families;
  int exit_code = 0;  // 0 pass (warnings allowed), 1 regression, 3 could not measure
  // About the document as a whole, said once: why it cannot pass though no scene failed (no
  // scenes, incomplete), and notes that judge nothing (no goldens: "… (4 scenes); bless …").
  std::vector<std::string> problems;
  std::vector<std::string> notes;

  std::size_t count(GateOutcome outcome) const;
};

GateResult evaluate_gate(const ResultsDocument& document, const GatePolicy& policy);

std::string_view to_string(GateOutcome outcome);

}  // namespace raygate

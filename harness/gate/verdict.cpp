#include "gate/verdict.h"

#include <fmt/core.h>

#include <algorithm>

#include "core/exit_codes.h"
#include "measure/change.h"

namespace raygate {

namespace {

void raise(SceneGate& gate, GateOutcome outcome, std::string reason) {
  gate.outcome = std::max(gate.outcome, outcome);
  gate.reasons.push_back(std::move(reason));
}

std::string percent(double fraction) { return fmt::format("{:+.1f}%", 100.0 * fraction); }

// A crash of head where base ran is the change's doing; anything else failing is not.
void judge_failure(const ResultsDocument& document, const SceneResult& scene, SceneGate& gate) {
  const RunRecord& run = *scene.runs.failed_run;
  gate.speed = "FAILED";
  const std::string what = fmt::format("{} {}: {} (log: {})", scene.runs.failed_role,
                                       run.outcome, run.failure, run.log.string());
  const bool head_only = document.kind == "compare" && scene.runs.failed_role == "head" &&
                         scene.runs.first_run("base") != nullptr;
  raise(gate, head_only ? GateOutcome::fail : GateOutcome::unmeasured,
        head_only ? "head failed where base ran: " + what : what);
}

void judge_speed(const SceneResult& scene, const ScenePolicy& policy, bool fail_on_inconclusive,
                 SceneGate& gate) {
  if (!scene.change) {
    gate.speed = "MEASURED";
    return;
  }
  const ChangeSummary& change = *scene.change;
  const ChangeVerdict verdict = classify_change(change, policy.max_slowdown);
  gate.speed = std::string(to_string(verdict));
  const std::string numbers = fmt::format(
      "head vs base {} (95% CI {} to {}), ratio {:.3f} -> {:.3f}, {} rounds, limit {}",
      percent(change.change), percent(change.change_interval.lower),
      percent(change.change_interval.upper), change.base.ratio, change.head.ratio, change.rounds,
      percent(policy.max_slowdown));
  if (verdict == ChangeVerdict::regressed) raise(gate, GateOutcome::fail, "slower: " + numbers);
  if (verdict == ChangeVerdict::inconclusive) {
    raise(gate, fail_on_inconclusive ? GateOutcome::fail : GateOutcome::warn,
          "inconclusive: " + numbers);
  }
}

int image_rank(const std::string& verdict) {
  if (verdict == "fail") return 4;
  if (verdict == "error") return 3;
  if (verdict == "missing") return 2;
  if (verdict == "warn") return 1;
  return 0;
}

void judge_images(const SceneResult& scene, SceneGate& gate) {
  for (const ImageCheck& check : scene.images) {
    if (image_rank(check.verdict) > image_rank(gate.image) || gate.image.empty()) {
      gate.image = check.verdict;
    }
    const std::string who = fmt::format("image {} vs {}", check.role, check.reference);
    if (check.verdict == "fail" || check.verdict == "warn") {
      raise(gate, check.verdict == "fail" ? GateOutcome::fail : GateOutcome::warn,
            fmt::format("{}: {}", who, summarize(*check.metrics)));
    } else if (check.verdict == "missing") {
      raise(gate, GateOutcome::warn, fmt::format("{}: {}", who, check.error));
    } else if (check.verdict == "error") {
      raise(gate, GateOutcome::unmeasured, fmt::format("{}: {}", who, check.error));
    }
  }
}

}  // namespace

std::size_t GateResult::count(GateOutcome outcome) const {
  return static_cast<std::size_t>(std::count_if(
      scenes.begin(), scenes.end(), [&](const SceneGate& s) { return s.outcome == outcome; }));
}

GateResult evaluate_gate(const ResultsDocument& document, const GatePolicy& policy) {
  GateResult result;
  for (const SceneResult& scene : document.scenes) {
    SceneGate gate;
    gate.id = scene.entry.id;
    if (scene.runs.failed()) {
      judge_failure(document, scene, gate);
    } else {
      judge_speed(scene, policy.for_scene(scene.entry.id), policy.fail_on_inconclusive, gate);
    }
    judge_images(scene, gate);
    result.scenes.push_back(std::move(gate));
  }
  const bool incomplete = !document.complete;
  if (result.count(GateOutcome::fail) > 0) {
    result.exit_code = to_int(ExitCode::regression);
  } else if (result.count(GateOutcome::unmeasured) > 0 || incomplete) {
    result.exit_code = to_int(ExitCode::infrastructure);
  } else {
    result.exit_code = to_int(ExitCode::pass);
  }
  return result;
}

std::string_view to_string(GateOutcome outcome) {
  switch (outcome) {
    case GateOutcome::pass: return "pass";
    case GateOutcome::warn: return "warn";
    case GateOutcome::fail: return "fail";
    case GateOutcome::unmeasured: return "unmeasured";
  }
  return "unmeasured";
}

}  // namespace raygate

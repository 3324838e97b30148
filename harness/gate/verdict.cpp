#include "gate/verdict.h"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "core/exit_codes.h"
#include "core/format.h"
#include "gate/growth_gate.h"
#include "gate/memory_gate.h"
#include "gate/runner_noise.h"
#include "measure/change.h"

namespace raygate {

namespace {

// `part` is the scene's speed_outcome or image_outcome (or nullptr: memory, which has none of
// its own); the scene's outcome is the worst of everything raised.
void raise(SceneGate& gate, GateOutcome* part, GateOutcome outcome, std::string reason) {
  gate.outcome = std::max(gate.outcome, outcome);
  if (part != nullptr) *part = std::max(*part, outcome);
  gate.reasons.push_back(std::move(reason));
}

void raise_speed(SceneGate& gate, GateOutcome outcome, std::string reason) {
  raise(gate, &gate.speed_outcome, outcome, std::move(reason));
}

void raise_image(SceneGate& gate, GateOutcome outcome, std::string reason) {
  raise(gate, &gate.image_outcome, outcome, std::move(reason));
}

// "head: tracer killed by SIGSEGV (log: ...)" when the failure is the process's end; "baseline
// exited with status 0, but raygate-baseline took no measurable ... (log: ...)" when it ended
// well and failed after (a tiny run's "exited with status 0: ..." read as if 0 were the problem).
std::string failure_text(Role role, const RunRecord& run) {
  if (run.failure.find(run.outcome) != std::string::npos) {
    return fmt::format("{}: {} (log: {})", to_string(role), run.failure, run.log.string());
  }
  return fmt::format("{} {}, but {} (log: {})", to_string(role), run.outcome, run.failure,
                     run.log.string());
}

// A crash of head where base ran is the change's doing; anything else failing is not, nor is a
// run raygate's own time budget stopped (docs/statistics.md §6c: exit 3).
void judge_failure(const ResultsDocument& document, const SceneResult& scene, SceneGate& gate) {
  const RunRecord& run = *scene.runs.failed_run;
  gate.speed = SpeedVerdict::failed;
  const std::string what = failure_text(scene.runs.failed_role, run);
  const bool head_only = is_compare(document.kind) && scene.runs.failed_role == Role::head &&
                         scene.runs.first_run(Role::base) != nullptr && !run.stopped_by_budget;
  raise_speed(gate, head_only ? GateOutcome::fail : GateOutcome::unmeasured,
              head_only ? "head failed where base ran: " + what : what);
}

void judge_speed(const SceneResult& scene, const ScenePolicy& policy, bool fail_on_inconclusive,
                 SceneGate& gate) {
  if (!scene.change) {
    gate.speed = SpeedVerdict::measured;
    return;
  }
  const ChangeSummary& change = *scene.change;
  const ChangeVerdict verdict = classify_change(change, policy.max_slowdown);
  gate.speed = speed_verdict(verdict);
  gate.speed_limit = policy.max_slowdown;
  // The same words as the reports' change column (measure/change.h change_with_interval).
  const std::string numbers = fmt::format(
      "head vs base {}, ratio {:.3f} -> {:.3f}, {}, limit {}",
      change_with_interval(change, verdict, policy.max_slowdown), change.base.ratio,
      change.head.ratio, count_text(change.rounds, "round"), signed_percent(policy.max_slowdown));
  if (verdict == ChangeVerdict::regressed) {
    raise_speed(gate, GateOutcome::fail, "slower: " + numbers);
  }
  if (verdict == ChangeVerdict::inconclusive) {
    raise_speed(gate, fail_on_inconclusive ? GateOutcome::fail : GateOutcome::warn,
                "inconclusive: " + numbers);
  }
}

// Peak memory is judged beside speed: a scene may be as fast and still no longer fit its node.
void judge_memory(const SceneResult& scene, const ScenePolicy& policy, bool fail_on_inconclusive,
                  SceneGate& gate) {
  const std::optional<MemoryJudgement> judged = judge_scene_memory(scene, policy);
  if (!judged) return;
  gate.memory = judged->verdict;
  if (judged->verdict == ChangeVerdict::regressed) {
    raise(gate, nullptr, GateOutcome::fail, "more memory: " + describe_memory(*judged));
  } else if (judged->verdict == ChangeVerdict::inconclusive) {
    raise(gate, nullptr, fail_on_inconclusive ? GateOutcome::fail : GateOutcome::warn,
          "memory inconclusive: " + describe_memory(*judged));
  }
}

// The same "no golden" words from many scenes (a tracer without goldens), counted to say once.
// Images without a golden, by why: a compare has two per scene (base and head), so the note
// counts scenes, and images only where they are more.
struct MissingGolden {
  std::string why;
  std::size_t images = 0;
  std::set<std::string> scenes;
};
using MissingGoldens = std::vector<MissingGolden>;

void count_missing(MissingGoldens& missing, const std::string& why, const std::string& scene) {
  auto found = std::find_if(missing.begin(), missing.end(),
                            [&](const MissingGolden& m) { return m.why == why; });
  if (found == missing.end()) found = missing.insert(missing.end(), MissingGolden{why, 0, {}});
  ++found->images;
  found->scenes.insert(scene);
}

// "2 scenes", or "4 images: 2 scenes × base and head".
std::string missing_count(const MissingGolden& m, const ResultsDocument& document) {
  const std::string scenes = count_text(m.scenes.size(), "scene");
  if (m.images == m.scenes.size()) return scenes;
  if (is_compare(document.kind) && m.images == 2 * m.scenes.size()) {
    return fmt::format("{} images: {} × base and head", m.images, scenes);
  }
  return fmt::format("{} images of {}", m.images, scenes);
}

void judge_images(const SceneResult& scene, bool fail_on_inconclusive, SceneGate& gate,
                  MissingGoldens& missing) {
  for (const ImageCheck& check : scene.images) {
    // The enum's order is the verdicts' rank (compare/image_verdict.h).
    gate.image = std::max(gate.image.value_or(check.verdict), check.verdict);
    const std::string who =
        fmt::format("image {} vs {}", to_string(check.role), to_string(check.reference));
    // A failed image without metrics could not be read, or is broken in a way its error says.
    const std::string what = check_detail(check);
    if (check.failed() && check.role == Role::base) {
      // The base revision is the reference a compare judges head against: a broken base image
      // means the change could not be checked (exit 3), not that the change broke it.
      raise_image(gate, GateOutcome::unmeasured,
                  fmt::format("{}: {} (the base revision's image is broken, so the change could "
                              "not be checked)",
                              who, what));
    } else if (check.verdict == ImageVerdict::inconclusive) {
      // Like a speed change the budget could not decide: a warning, or with
      // fail_on_inconclusive a failure.
      raise_image(gate, fail_on_inconclusive ? GateOutcome::fail : GateOutcome::warn,
                  fmt::format("{}: {}", who, what));
    } else if (check.verdict == ImageVerdict::fail || check.verdict == ImageVerdict::warn) {
      raise_image(gate, check.failed() ? GateOutcome::fail : GateOutcome::warn,
                  fmt::format("{}: {}", who, what));
    } else if (check.verdict == ImageVerdict::missing) {
      count_missing(missing, check.error, scene.entry.id);  // a note for the document
    } else if (check.verdict == ImageVerdict::error) {
      raise_image(gate, GateOutcome::unmeasured, fmt::format("{}: {}", who, check.error));
    }
  }
}

// One note per distinct reason, with how to get goldens: look at the images first, then bless.
std::vector<std::string> missing_golden_notes(const MissingGoldens& missing,
                                              const ResultsDocument& document) {
  const std::string role = is_compare(document.kind) ? " --role head" : "";
  std::vector<std::string> notes;
  for (const MissingGolden& m : missing) {
    notes.push_back(fmt::format(
        "images not checked against goldens: {} ({}); look at the images, then bless them: "
        "raygate golden bless --from-run RESULTS.json{} --golden-dir DIR (a folder kept with "
        "your tracer, then given to run and compare; without it, raygate's golden/<adapter>/)",
        m.why, missing_count(m, document), role));
  }
  return notes;
}

// Why a document cannot pass though no scene says so.
std::vector<std::string> document_problems(const ResultsDocument& document) {
  if (document.scenes.empty()) return {"the document holds no scenes: nothing was measured"};
  if (!document.complete) {
    // A partial merge is incomplete too: "the run stopped" was not what happened to its shard.
    return {
        fmt::format("the document is incomplete: it holds {} {} (its run stopped early, or "
                    "a merge lacked shards)",
                    document.scenes.size(), document.scenes.size() == 1 ? "scene" : "scenes")};
  }
  return {};
}

bool failed_growth(const GateResult& result) {
  return std::any_of(result.families.begin(), result.families.end(),
                     [](const SceneGate& g) { return g.outcome == GateOutcome::fail; });
}

// A policy's scene overrides that name no scene of the document: a misspelt id has no effect,
// which would otherwise go unsaid (the sweep of 2026-11-28); a shard's document names them too.
std::optional<std::string> unused_overrides_note(const ResultsDocument& document,
                                                 const GatePolicy& policy) {
  std::vector<std::string> unused;
  for (const auto& [id, scene_policy] : policy.scenes) {
    const bool used = std::any_of(document.scenes.begin(), document.scenes.end(),
                                  [&](const SceneResult& s) { return s.entry.id == id; });
    if (!used) unused.push_back("'" + id + "'");
  }
  if (unused.empty()) return std::nullopt;
  return fmt::format(
      "the policy's overrides for {} match no scene of this document: no effect here",
      fmt::join(unused, ", "));
}

}  // namespace

std::size_t GateResult::count(GateOutcome outcome) const {
  return static_cast<std::size_t>(std::count_if(
      scenes.begin(), scenes.end(), [&](const SceneGate& s) { return s.outcome == outcome; }));
}

GateResult evaluate_gate(const ResultsDocument& document, const GatePolicy& policy) {
  GateResult result;
  MissingGoldens missing;
  for (const SceneResult& scene : document.scenes) {
    SceneGate gate;
    gate.id = scene.entry.id;
    if (scene.runs.failed()) {
      judge_failure(document, scene, gate);
    } else if (is_compare(document.kind) && !scene.change) {
      // A compare judges head against base: a scene with no change measured judged nothing
      // (a hand-edited "change": null passed as "measured").
      gate.speed = SpeedVerdict::measured;
      raise_speed(gate, GateOutcome::unmeasured, "no change of head against base was measured");
    } else {
      judge_speed(scene, policy.for_scene(scene.entry.id), policy.fail_on_inconclusive, gate);
      judge_memory(scene, policy.for_scene(scene.entry.id), policy.fail_on_inconclusive, gate);
    }
    judge_images(scene, policy.fail_on_inconclusive, gate, missing);
    result.scenes.push_back(std::move(gate));
  }
  result.families = judge_growth(document, policy);
  result.notes = missing_golden_notes(missing, document);
  if (std::optional<std::string> noise = runner_noise_note(document, policy)) {
    result.notes.push_back(std::move(*noise));
  }
  if (std::optional<std::string> unused = unused_overrides_note(document, policy)) {
    result.notes.push_back(std::move(*unused));
  }
  result.problems = document_problems(document);
  if (result.count(GateOutcome::fail) > 0 || failed_growth(result)) {
    result.exit_code = to_int(ExitCode::regression);
  } else if (result.count(GateOutcome::unmeasured) > 0 || !result.problems.empty()) {
    result.exit_code = to_int(ExitCode::infrastructure);
  } else {
    result.exit_code = to_int(ExitCode::pass);
  }
  return result;
}

std::string_view to_string(SpeedVerdict verdict) {
  switch (verdict) {
    case SpeedVerdict::measured: return "MEASURED";
    case SpeedVerdict::failed: return "FAILED";
    case SpeedVerdict::unchanged: return to_string(ChangeVerdict::unchanged);
    case SpeedVerdict::improved: return to_string(ChangeVerdict::improved);
    case SpeedVerdict::regressed: return to_string(ChangeVerdict::regressed);
    case SpeedVerdict::inconclusive: return to_string(ChangeVerdict::inconclusive);
  }
  return "FAILED";
}

SpeedVerdict speed_verdict(ChangeVerdict verdict) {
  switch (verdict) {
    case ChangeVerdict::unchanged: return SpeedVerdict::unchanged;
    case ChangeVerdict::improved: return SpeedVerdict::improved;
    case ChangeVerdict::regressed: return SpeedVerdict::regressed;
    case ChangeVerdict::inconclusive: return SpeedVerdict::inconclusive;
  }
  return SpeedVerdict::inconclusive;
}

std::optional<ChangeVerdict> change_verdict_of(SpeedVerdict verdict) {
  switch (verdict) {
    case SpeedVerdict::unchanged: return ChangeVerdict::unchanged;
    case SpeedVerdict::improved: return ChangeVerdict::improved;
    case SpeedVerdict::regressed: return ChangeVerdict::regressed;
    case SpeedVerdict::inconclusive: return ChangeVerdict::inconclusive;
    case SpeedVerdict::measured:
    case SpeedVerdict::failed: break;
  }
  return std::nullopt;
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

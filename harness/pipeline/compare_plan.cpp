#include "pipeline/compare_plan.h"

#include <fmt/core.h>

#include <algorithm>
#include <span>

#include "compare/noisy_image_check.h"
#include "core/format.h"
#include "measure/fastest_of_two.h"
#include "pipeline/compare_family.h"
#include "pipeline/explain_stage.h"
#include "pipeline/run_images.h"
#include "pipeline/stored_ratio.h"
#include "pipeline/visit_plan.h"

namespace raygate {

namespace {

// A Monte Carlo tracer's images: head's runs against base's, within noise, judged on the runs of
// the last look the stop rule took (pipeline/image_stop.h), at a look's share of the rates.
ImageCheck check_noisy_change(const SceneResult& scene, std::size_t family_size, double tolerance,
                              const std::filesystem::path& evidence_dir) {
  const SceneRuns looked = image_look_runs(scene.runs);
  return check_noisy_images(Role::head, ImageReference::base, run_images(looked, Role::head),
                            run_images(looked, Role::base),
                            image_look_thresholds(family_size, tolerance), evidence_dir,
                            scene.entry.id + ".head-vs-base");
}

// Head's image against base's: within noise for a Monte Carlo tracer (against all of base's
// runs; `noisy_family`: the images the check's 1% is shared by), else pixel by pixel.
void check_head_image(SceneResult& scene, const ScenePolicy& policy,
                      const std::filesystem::path& evidence_dir,
                      std::optional<NoisyImageFamily> noisy_family) {
  const RunRecord* base = scene.runs.first_run(Role::base);
  const RunRecord* head = scene.runs.first_run(Role::head);
  if (base == nullptr || head == nullptr) return;
  if (noisy_family) {
    scene.images.push_back(
        check_noisy_change(scene, noisy_family->images, policy.image_tolerance, evidence_dir));
    return;
  }
  scene.images.push_back(check_image(Role::head, ImageReference::base, head->image, base->image,
                                     policy.image, evidence_dir, scene.entry.id + ".head-vs-base"));
}

}  // namespace

std::size_t compare_family_size(const MeasureContext& context, const SuiteMeasurement& m) {
  return context.shard ? context.shard->suite_scenes.size() : m.scenes.size();
}

ComparePlan::ComparePlan(const MeasureContext& context, const SuiteMeasurement& m,
                         const Contender& base, const Contender& head, PipelineIo& io,
                         bool ratio_rounds)
    : context_(context),
      m_(m),
      base_(base),
      head_(head),
      io_(io),
      family_size_(compare_family_size(context, m)),
      alpha_(scene_decision_alpha(context.policy, family_size_)),
      budget_(context.stopping, m.scenes.size(), io.clock, revisit_reserve_scenes(m.scenes.size())),
      estimate_(estimate_shape(context, m.scenes.size(), "compare"),
                fewest_compare_rounds(context, alpha_), 2, io.progress),
      noisy_images_(m.images == ImageKind::monte_carlo
                        ? std::optional(NoisyImageFamily{family_size_})
                        : std::nullopt),
      ratio_rounds_(ratio_rounds) {}

StopRule ComparePlan::scene_stop_rule(const StoppingPolicy& share,
                                      const std::string& scene_id) const {
  const ScenePolicy& policy = context_.policy.for_scene(scene_id);
  return compare_stop_rule(share, policy, scene_levels(policy, alpha_), exact_timing(context_),
                           noisy_images_);
}

StopRule ComparePlan::first_visit_stop(const SuiteScene& scene) {
  return estimate_.watch(scene_stop_rule(budget_.next_scene(), scene.id), scene.id);
}

RepeatChooser ComparePlan::repeats(const SuiteScene& scene) const {
  if (!context_.repeat_where_it_pays || exact_timing(context_)) return {};
  const ScenePolicy& policy = context_.policy.for_scene(scene.id);
  return [&policy, alpha = alpha_](const SceneRuns& so_far) -> std::size_t {
    if (so_far.rounds.size() < 2 * kMinPairsForSpread) return 1;  // no spread yet
    const ChangeSummary change =
        measured_change(compare_samples(so_far.rounds), change_bootstrap(policy), false,
                        scene_levels(policy, alpha));
    return next_round_repeats(so_far, change, policy.max_slowdown);
  };
}

// The change head vs base at the scene's share of the family, on the scene's first
// `change_rounds` rounds: a change decided before ratio rounds stays judged on the rounds it was
// decided on. Its base ratio is over every round the baseline joined, head's through the change
// (ratio_through_change), so the two ratio columns and the change agree in sign and size.
void ComparePlan::judge_change(SceneResult& scene, std::size_t change_rounds) const {
  const ScenePolicy& policy = context_.policy.for_scene(scene.entry.id);
  const std::vector<CompareRound> rounds = compare_samples(scene.runs.rounds);
  const std::span<const CompareRound> judged(rounds.data(), std::min(change_rounds, rounds.size()));
  scene.change = measured_change(judged, change_bootstrap(policy), exact_timing(context_),
                                 scene_levels(policy, alpha_));
  scene.change_verdict = classify_change(*scene.change, policy.max_slowdown);
  if (judged.size() < rounds.size()) {
    const double confidence = change_bootstrap(policy).confidence;
    scene.change->base = summarize_ratio(round_samples(scene.runs.rounds, Role::base), confidence);
    scene.change->head = ratio_through_change(
        scene.change->base,
        summarize_ratio(round_samples(scene.runs.rounds, Role::head), confidence),
        scene.change->change);
  }
  // The document's ratios are the change's.
  if (scene.change->base.rounds > 0) {
    scene.ratios[Role::base] = scene.change->base;
    scene.ratios[Role::head] = scene.change->head;
  }
}

void ComparePlan::finish_scene(SceneResult& scene) {
  judge_change(scene, scene.runs.rounds.size());
  check_head_image(scene, context_.policy.for_scene(scene.entry.id), m_.work_dir / "evidence",
                   noisy_images_);
}

std::optional<StopRule> ComparePlan::revisit_stop(const SceneResult& scene, std::size_t scenes_left,
                                                  double seconds_to_decide) {
  const StoppingPolicy again =
      budget_.again(scene.runs.seconds_spent, scenes_left, seconds_to_decide);
  if (again.max_seconds <= scene.runs.seconds_spent) return std::nullopt;
  return scene_stop_rule(again, scene.entry.id);
}

VisitPlan ComparePlan::plan_visit(const SceneResult& scene) const {
  return raygate::plan_visit(scene, context_.policy, context_.repeat_where_it_pays);
}

void ComparePlan::rejudge(SceneResult& scene) { judge_change(scene, scene.runs.rounds.size()); }

bool ComparePlan::wants_ratio_rounds(const SceneResult& scene) const {
  const RatioSummary* ratio = scene.ratio(Role::base);
  return ratio_rounds_ && !exact_timing(context_) && ratio != nullptr &&
         !stored_ratio_precise(*ratio, stored_ratio_confidence(context_.policy, scene.entry.id));
}

std::optional<StopRule> ComparePlan::ratio_rounds_stop(const SceneResult& scene,
                                                       std::size_t scenes_left) {
  const double confidence = stored_ratio_confidence(context_.policy, scene.entry.id);
  const RatioSummary& ratio = *scene.ratio(Role::base);
  if (const std::size_t needed = stored_ratio_rounds_needed(ratio, confidence);
      needed > kStoredRatioMaxRounds) {
    ratio_why_[scene.entry.id] = fmt::format(
        "its rounds differ by {:.1f}%: about {} baseline rounds would make it +-{:.0f}%, and "
        "ratio rounds stop at {}",
        100.0 * ratio.log_ratio_mad_scaled, needed, 100.0 * kStoredRatioHalfWidth,
        kStoredRatioMaxRounds);
    return std::nullopt;
  }
  StoppingPolicy share = budget_.again(scene.runs.seconds_spent, scenes_left);
  const std::size_t rounds = scene.runs.rounds.size();
  // Within --max-rounds and the budget, as every round of the scene.
  const std::size_t rounds_allowed =
      std::min(share.max_rounds, rounds + stored_ratio_rounds_left(scene));
  if (rounds_allowed <= rounds) {
    ratio_why_[scene.entry.id] =
        rounds >= share.max_rounds
            ? fmt::format("--max-rounds {} left no ratio rounds", share.max_rounds)
            : fmt::format("ratio rounds stop at {} baseline rounds", kStoredRatioMaxRounds);
    return std::nullopt;
  }
  if (share.max_seconds <= scene.runs.seconds_spent) {
    ratio_why_[scene.entry.id] = "no time left in the budget for ratio rounds";
    return std::nullopt;
  }
  share.min_rounds = 1;
  share.max_rounds = rounds_allowed;
  return stored_ratio_stop_rule(share, confidence);
}

void ComparePlan::rejudge_after_ratio_rounds(SceneResult& scene, std::size_t rounds_before,
                                             const std::string& stop_reason) {
  const bool decided = scene.change && scene.change_verdict != ChangeVerdict::inconclusive;
  // An undecided change is judged on every round: its confidence sequences hold at each.
  judge_change(scene, decided ? rounds_before : scene.runs.rounds.size());
  ratio_why_[scene.entry.id] = fmt::format(
      "{}, then {}", count_text(scene.runs.rounds.size() - rounds_before, "ratio round"),
      stop_reason == to_string(StopDecision::stop_budget_time) ? "the budget ran out"
                                                               : "their round limit");
}

std::vector<std::string> ComparePlan::finish_suite(ResultsDocument& document) {
  std::vector<std::string> lines;
  for (const std::string& id : apply_family_control(document, context_.policy, family_size_)) {
    lines.push_back(id +
                    ": REGRESSED at its Holm share of the family (other scenes regressed "
                    "first)");
  }
  if (std::string undecided = undecided_line(document, context_.policy); !undecided.empty()) {
    lines.push_back(std::move(undecided));
  }
  if (std::string stored = stored_ratio_line(document, context_.policy, ratio_why_);
      !stored.empty()) {
    lines.push_back(std::move(stored));
  }
  for (std::string& line :
       explain_regressed_scenes(document, context_, m_, base_, head_, io_.executor)) {
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace raygate

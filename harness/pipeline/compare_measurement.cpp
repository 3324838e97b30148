#include "pipeline/compare_measurement.h"

#include <fmt/core.h>

#include <algorithm>
#include <limits>
#include <optional>

#include "core/time_text.h"
#include "measure/confidence_sequence.h"
#include "measure/fastest_of_two.h"
#include "measure/simulated_cost.h"
#include "compare/noisy_image_check.h"
#include "pipeline/compare_family.h"
#include "pipeline/run_images.h"
#include "pipeline/explain_stage.h"
#include "pipeline/image_stop.h"
#include "pipeline/measurement_estimate.h"
#include "pipeline/stop_rules.h"
#include "pipeline/visit_plan.h"
#include "runner/baseline_contender.h"
#include "runner/tracer_contender.h"

namespace raygate {

namespace {

// A Monte Carlo tracer's images: every run of head against every run of base, within noise.
ImageCheck check_noisy_change(const SceneResult& scene, std::size_t family_size, double tolerance,
                              const std::filesystem::path& evidence_dir) {
  return check_noisy_images(Role::head, ImageReference::base, run_images(scene.runs, Role::head),
                            run_images(scene.runs, Role::base),
                            noisy_thresholds_for(family_size, tolerance), evidence_dir,
                            scene.entry.id + ".head-vs-base");
}

// The change head vs base at the scene's share `alpha` of the family, and head's image against
// base's (against all of base's runs, within noise, when `noisy_family` is set: the number of
// images the Monte Carlo check's 1% is shared by).
void judge_change(SceneResult& scene, const GatePolicy& gate_policy, double alpha, bool counted) {
  const ScenePolicy& policy = gate_policy.for_scene(scene.entry.id);
  scene.change = measured_change(compare_samples(scene.runs.rounds), change_bootstrap(policy),
                                 counted, scene_levels(policy, alpha));
  scene.change_verdict = classify_change(*scene.change, policy.max_slowdown);
  // The document's ratios are the change's: head's through the change (ratio_through_change).
  if (scene.change->base.rounds > 0) {
    scene.ratios[Role::base] = scene.change->base;
    scene.ratios[Role::head] = scene.change->head;
  }
}

void finish_compare_scene(SceneResult& scene, const GatePolicy& gate_policy, double alpha,
                          const std::filesystem::path& evidence_dir, bool counted,
                          std::optional<std::size_t> noisy_family) {
  judge_change(scene, gate_policy, alpha, counted);
  const ScenePolicy& policy = gate_policy.for_scene(scene.entry.id);
  const RunRecord* base = scene.runs.first_run(Role::base);
  const RunRecord* head = scene.runs.first_run(Role::head);
  if (base != nullptr && head != nullptr && noisy_family) {
    scene.images.push_back(
        check_noisy_change(scene, *noisy_family, policy.image_tolerance, evidence_dir));
  } else if (base != nullptr && head != nullptr) {
    scene.images.push_back(check_image(Role::head, ImageReference::base, head->image, base->image,
                                       policy.image, evidence_dir,
                                       scene.entry.id + ".head-vs-base"));
  }
}

// A round budget below what a verdict needs makes the compare a slow way to print
// INCONCLUSIVE; say so before measuring, with the numbers (sim mode decides in two rounds).
std::optional<std::string> round_budget_warning(const MeasureContext& context, double alpha) {
  if (exact_timing(context)) return std::nullopt;
  const std::size_t max_rounds = context.stopping.max_rounds;
  const std::size_t to_regress = min_values_for_median_sequence(alpha);
  std::size_t to_pass = to_regress;
  for (const SuiteScene& scene : context.scenes) {
    to_pass = std::min(
        to_pass, min_values_for_median_sequence(context.policy.for_scene(scene.id).significance));
  }
  if (max_rounds >= to_regress) return std::nullopt;
  if (max_rounds < to_pass) {
    return fmt::format(
        "warning: --max-rounds {} allows no verdict: a scene needs {} rounds to be "
        "UNCHANGED and {} to be REGRESSED, so every scene will be INCONCLUSIVE",
        max_rounds, to_pass, to_regress);
  }
  return fmt::format(
      "warning: --max-rounds {} cannot find a regression: REGRESSED needs {} "
      "rounds at this family's significance (UNCHANGED {})",
      max_rounds, to_regress, to_pass);
}

}  // namespace

MeasuredDocument measure_compare(const CompareRequest& request, PipelineIo& io) {
  const MeasureContext& context = request.context;
  const std::string source_hash = request.baseline.source_hash();
  // Both sides are built before either failure is reported, so one job says whether each builds.
  const BuildRecord base_build =
      build_revision(request.base, context, source_hash, context.jobs, io.progress);
  const BuildRecord head_build =
      build_revision(request.head, context, source_hash, context.jobs, io.progress);
  require_both_built(base_build, head_build);
  require_run_program(context.adapter, base_build, request.base.path, context.tools.data_root);
  require_run_program(context.adapter, head_build, request.head.path, context.tools.data_root);
  const PreparedRevision base =
      prepared_revision(Role::base, request.repository, request.base, context, base_build);
  const PreparedRevision head =
      prepared_revision(Role::head, request.repository, request.head, context, head_build);
  return measure_prepared_compare(request, base, head, io);
}

MeasuredDocument measure_prepared_compare(const CompareRequest& request,
                                          const PreparedRevision& base,
                                          const PreparedRevision& head, PipelineIo& io) {
  const MeasureContext& context = request.context;
  SuiteMeasurement m = suite_measurement(
      context,
      compact_utc_timestamp() + "-" + request.base.short_sha + "-" + request.head.short_sha,
      request.out);
  const std::filesystem::path work_dir = m.work_dir;
  m.tracer_roles = {Role::base, Role::head};
  // The family is the whole selection, so a shard's scenes get the share they would have had
  // in one job (docs/statistics.md §6c).
  const std::size_t family_size =
      context.shard ? context.shard->suite_scenes.size() : m.scenes.size();
  const double alpha = scene_decision_alpha(context.policy, family_size);
  if (const auto warning = round_budget_warning(context, alpha)) io.progress.line(*warning);
  const BaselineContender baseline_runs =
      baseline_contender(context, request.baseline.source_hash());
  const TracerContender base_runs(base.setup);
  const TracerContender head_runs(head.setup);
  SuiteBudget budget(context.stopping, m.scenes.size(), io.clock,
                     revisit_reserve_scenes(m.scenes.size()));
  MeasurementEstimate estimate(estimate_shape(context, m.scenes.size(), "compare"),
                               fewest_compare_rounds(context, alpha), 2, io.progress);
  // A Monte Carlo image still inconclusive keeps its scene measuring (pipeline/image_stop.h).
  const std::optional<NoisyImageFamily> noisy_images =
      m.images == ImageKind::monte_carlo ? std::optional(NoisyImageFamily{family_size})
                                         : std::nullopt;
  m.stop = [&](const SuiteScene& scene) {
    const ScenePolicy& policy = context.policy.for_scene(scene.id);
    return estimate.watch(compare_stop_rule(budget.next_scene(), policy,
                                            scene_levels(policy, alpha), exact_timing(context),
                                            noisy_images),
                          scene.id);
  };
  if (context.repeat_where_it_pays && !exact_timing(context)) {
    m.repeats = [&](const SuiteScene& entry) -> RepeatChooser {
      const ScenePolicy& policy = context.policy.for_scene(entry.id);
      return [&policy, alpha](const SceneRuns& so_far) -> std::size_t {
        if (so_far.rounds.size() < 2 * kMinPairsForSpread) return 1;  // no spread yet
        const ChangeSummary change =
            measured_change(compare_samples(so_far.rounds), change_bootstrap(policy), false,
                            scene_levels(policy, alpha));
        return next_round_repeats(so_far, change, policy.max_slowdown);
      };
    };
  }
  m.revisits =
      SceneRevisits{[&](const SceneResult& scene, std::size_t scenes_left,
                        double seconds_needed) -> std::optional<StopRule> {
                      const ScenePolicy& policy = context.policy.for_scene(scene.entry.id);
                      const StoppingPolicy again =
                          budget.again(scene.runs.seconds_spent, scenes_left, seconds_needed);
                      if (again.max_seconds <= scene.runs.seconds_spent) return std::nullopt;
                      return compare_stop_rule(again, policy, scene_levels(policy, alpha),
                                               exact_timing(context), noisy_images);
                    },
                    [&](const SceneResult& scene) {
                      return plan_visit(scene, context.policy, context.repeat_where_it_pays);
                    },
                    [&](SceneResult& scene) {
                      judge_change(scene, context.policy, alpha, exact_timing(context));
                    }};
  m.finish_scene = [&](SceneResult& scene) {
    finish_compare_scene(scene, context.policy, alpha, work_dir / "evidence", exact_timing(context),
                         noisy_images ? std::optional(noisy_images->images) : std::nullopt);
  };
  m.finish_suite = [&](ResultsDocument& document) {
    std::vector<std::string> lines;
    for (const std::string& id : apply_family_control(document, context.policy, family_size)) {
      lines.push_back(id +
                      ": REGRESSED at its Holm share of the family (other scenes regressed "
                      "first)");
    }
    if (std::string undecided = undecided_line(document, context.policy); !undecided.empty()) {
      lines.push_back(std::move(undecided));
    }
    for (std::string& line :
         explain_regressed_scenes(document, context, m, base_runs, head_runs, io.executor)) {
      lines.push_back(std::move(line));
    }
    return lines;
  };
  m.contenders = {&baseline_runs, &base_runs, &head_runs};

  ResultsDocument document = new_document(DocumentKind::compare, context, request.baseline);
  document.revisions = {base.record, head.record};
  const std::string opening = fmt::format(
      "comparing {} {} (base) with {} (head) against {} on suite {}: {} scenes{}",
      context.adapter.name, request.base.short_sha, request.head.short_sha,
      request.baseline.version_line(), context.suite.name, m.scenes.size(), shard_note(context));
  return measure_document(std::move(document), m, opening, io);
}

}  // namespace raygate

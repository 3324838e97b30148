#include "cli/compare_session.h"

#include <fmt/core.h>

#include <algorithm>

#include "cli/measure_session.h"
#include "cli/revision_setup.h"
#include "cli/simulated_mode.h"
#include "measure/simulated_cost.h"
#include "core/time_text.h"
#include "gate/growth_gate.h"
#include "runner/baseline_contender.h"
#include "runner/tracer_contender.h"
#include "scaling/scaling_stage.h"

namespace raygate::cli {

namespace {

BootstrapOptions bootstrap_for(const ScenePolicy& policy) {
  BootstrapOptions options;
  options.confidence = 1.0 - policy.significance;
  return options;
}

// The change head vs base: exact when counted (sim mode) and every run repeated its count, else
// the statistics of timed rounds.
ChangeSummary measured_change(const std::vector<Round>& rounds, const ScenePolicy& policy,
                              bool counted) {
  const std::vector<CompareRound> samples = compare_samples(rounds);
  if (counted) {
    if (std::optional<ChangeSummary> exact = exact_change(samples)) return *exact;
  }
  return summarize_change(samples, bootstrap_for(policy));
}

// The change head vs base, and head's image against base's.
void finish_compare_scene(SceneResult& scene, const GatePolicy& gate_policy,
                          const std::filesystem::path& evidence_dir, bool counted) {
  const ScenePolicy& policy = gate_policy.for_scene(scene.entry.id);
  scene.change = measured_change(scene.runs.rounds, policy, counted);
  scene.change_verdict = std::string(to_string(classify_change(*scene.change, policy.max_slowdown)));
  const RunRecord* base = scene.runs.first_run("base");
  const RunRecord* head = scene.runs.first_run("head");
  if (base != nullptr && head != nullptr) {
    scene.images.push_back(check_image("head", "base", head->image, base->image, policy.image,
                                       evidence_dir, scene.entry.id + ".head-vs-base"));
  }
}

}  // namespace

StopRule change_stop_rule(const StoppingPolicy& stopping, const ScenePolicy& policy,
                          bool counted) {
  return [=](const std::vector<Round>& rounds, double seconds_spent) {
    // One round's interval is a point: never call that decided.
    if (rounds.size() >= std::max<std::size_t>(stopping.min_rounds, 2)) {
      const ChangeSummary change = measured_change(rounds, policy, counted);
      if (classify_change(change, policy.max_slowdown) != ChangeVerdict::inconclusive) {
        return StopDecision::stop_converged;
      }
    }
    if (rounds.size() >= stopping.max_rounds) return StopDecision::stop_budget_rounds;
    if (seconds_spent >= stopping.max_seconds) return StopDecision::stop_budget_time;
    return StopDecision::continue_measuring;
  };
}

ResultsDocument measure_compare(const CompareSetup& setup, std::filesystem::path* document_path) {
  const MeasureContext& context = setup.context;
  const std::string source_hash = setup.baseline.source_hash();
  const int jobs = context.jobs;
  const PreparedRevision base =
      prepare_revision("base", setup.repository, setup.base, context, source_hash, jobs);
  const PreparedRevision head =
      prepare_revision("head", setup.repository, setup.head, context, source_hash, jobs);

  SuiteMeasurement m = suite_measurement(
      context, compact_utc_timestamp() + "-" + setup.base.short_sha + "-" + setup.head.short_sha,
      setup.out);
  const std::filesystem::path work_dir = m.work_dir;
  m.tracer_roles = {"base", "head"};
  m.stop = [&](const SuiteScene& scene) {
    return change_stop_rule(context.stopping, context.policy.for_scene(scene.id),
                            simulated(context));
  };
  m.finish_scene = [&](SceneResult& scene) {
    finish_compare_scene(scene, context.policy, work_dir / "evidence", simulated(context));
  };
  const BaselineContender baseline_runs = make_baseline_contender(context, source_hash);
  const TracerContender base_runs(base.setup);
  const TracerContender head_runs(head.setup);
  m.contenders = {&baseline_runs, &base_runs, &head_runs};

  ResultsDocument document = new_document("compare", context, setup.baseline);
  document.revisions = {base.record, head.record};
  if (!context.quiet) {
    fmt::print(stderr, "comparing {} {} (base) with {} (head) against {} on suite {}: {} scenes{}\n",
             context.adapter.name, setup.base.short_sha, setup.head.short_sha,
             setup.baseline.version_line(), context.suite.name, m.scenes.size(),
             shard_note(context));
  }
  SystemExecutor executor;
  SteadyClock clock;
  {
    Progress progress(context.quiet ? nullptr : stderr, is_terminal(stderr));
    measure_suite(document, m, executor, clock, progress);
  }
  document.finished_at = utc_timestamp();
  attach_scaling(document, scaling_limits(context.policy), context.quiet ? nullptr : stderr);
  write_results(document, m.out);
  if (document_path != nullptr) *document_path = m.out;
  return document;
}

}  // namespace raygate::cli

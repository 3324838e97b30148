#include "pipeline/run_measurement.h"

#include <fmt/core.h>

#include "core/format.h"
#include "core/time_text.h"
#include "pipeline/measurement_estimate.h"
#include "pipeline/measurement_plan.h"
#include "pipeline/ratio_repeats.h"
#include "pipeline/stop_rules.h"
#include "runner/tracer_contender.h"

namespace raygate {

namespace {

// How `run` decides: each scene's rounds stop once the tracer's normalized ratio is known to the
// target precision (--target), within the scene's share of the budget, in one pass; the
// baseline joins every round, since there the ratio is the measurement.
class RunPlan final : public MeasurementPlan {
 public:
  RunPlan(const MeasureContext& context, std::size_t scenes, PipelineIo& io)
      : context_(context),
        budget_(context.stopping, scenes, io.clock),
        estimate_(estimate_shape(context, scenes, "run"), rounds_to_decide(context.stopping), 1,
                  io.progress) {}

  StopRule first_visit_stop(const SuiteScene& scene) override {
    return estimate_.watch(ratio_stop_rule(budget_.next_scene(), Role::tracer), scene.id);
  }

  // Each side's fastest of two where the scene's rounds show it pays (pipeline/ratio_repeats.h).
  RepeatChooser repeats(const SuiteScene&) const override {
    if (!context_.repeat_where_it_pays) return {};
    return [](const SceneRuns& so_far) { return ratio_repeats(so_far.rounds, Role::tracer); };
  }

 private:
  const MeasureContext& context_;
  SuiteBudget budget_;
  MeasurementEstimate estimate_;
};

}  // namespace

MeasuredDocument measure_run(const RunRequest& request, PipelineIo& io) {
  const MeasureContext& context = request.context;
  const PreparedRevision tracer =
      prepare_revision(Role::tracer, request.repository, request.worktree, context,
                       request.baseline.source_hash(), context.jobs, io.progress);
  return measure_prepared_run(request, tracer, io);
}

MeasuredDocument measure_prepared_run(const RunRequest& request, const PreparedRevision& tracer,
                                      PipelineIo& io) {
  const MeasureContext& context = request.context;
  const Worktree& worktree = request.worktree;
  SuiteMeasurement m =
      suite_measurement(context, compact_utc_timestamp() + "-" + worktree.short_sha, request.out);
  RunPlan plan(context, m.scenes.size(), io);
  m.tracer_roles = {Role::tracer};
  const BaselineContender baseline_runs =
      baseline_contender(context, request.baseline.source_hash());
  const TracerContender tracer_runs(tracer.setup);
  m.contenders = {&baseline_runs, &tracer_runs};

  ResultsDocument document = new_document(DocumentKind::run, context, request.baseline);
  document.revisions.push_back(tracer.record);
  // An uncommitted folder outside git has no subject: "uncommitted ()" said nothing.
  const std::string subject = worktree.subject.empty() ? "" : " (" + worktree.subject + ")";
  const std::string opening =
      fmt::format("measuring {} {}{} against {} on suite {}: {}{}", context.adapter.name,
                  worktree.short_sha, subject, request.baseline.version_line(), context.suite.name,
                  count_text(m.scenes.size(), "scene"), shard_note(context));
  return measure_document(std::move(document), m, plan, opening, io);
}

}  // namespace raygate

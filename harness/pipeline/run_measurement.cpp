#include "pipeline/run_measurement.h"

#include <fmt/core.h>

#include "core/time_text.h"
#include "pipeline/measurement_estimate.h"
#include "pipeline/ratio_repeats.h"
#include "pipeline/stop_rules.h"
#include "runner/tracer_contender.h"

namespace raygate {

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
  SuiteBudget budget(context.stopping, m.scenes.size(), io.clock);
  MeasurementEstimate estimate(estimate_shape(context, m.scenes.size(), "run"),
                               rounds_to_decide(context.stopping), 1, io.progress);
  m.stop = [&](const SuiteScene& scene) {
    return estimate.watch(ratio_stop_rule(budget.next_scene(), Role::tracer), scene.id);
  };
  m.tracer_roles = {Role::tracer};
  if (context.repeat_where_it_pays) {
    m.repeats = [](const SuiteScene&) -> RepeatChooser {
      return [](const SceneRuns& so_far) { return ratio_repeats(so_far.rounds, Role::tracer); };
    };
  }
  const BaselineContender baseline_runs =
      baseline_contender(context, request.baseline.source_hash());
  const TracerContender tracer_runs(tracer.setup);
  m.contenders = {&baseline_runs, &tracer_runs};

  ResultsDocument document = new_document(DocumentKind::run, context, request.baseline);
  document.revisions.push_back(tracer.record);
  const std::string opening =
      fmt::format("measuring {} {} ({}) against {} on suite {}: {} scenes{}", context.adapter.name,
                  worktree.short_sha, worktree.subject, request.baseline.version_line(),
                  context.suite.name, m.scenes.size(), shard_note(context));
  return measure_document(std::move(document), m, opening, io);
}

}  // namespace raygate

#include "pipeline/compare_measurement.h"

#include <fmt/core.h>

#include <algorithm>
#include <limits>
#include <optional>

#include "core/format.h"
#include "core/time_text.h"
#include "measure/confidence_sequence.h"
#include "pipeline/compare_family.h"
#include "pipeline/compare_plan.h"
#include "runner/baseline_contender.h"
#include "runner/tracer_contender.h"

namespace raygate {

namespace {

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
  m.tracer_roles = {Role::base, Role::head};
  const double alpha = scene_decision_alpha(context.policy, compare_family_size(context, m));
  if (const auto warning = round_budget_warning(context, alpha)) io.progress.line(*warning);
  const BaselineContender baseline_runs =
      baseline_contender(context, request.baseline.source_hash());
  const TracerContender base_runs(base.setup);
  const TracerContender head_runs(head.setup);
  m.contenders = {&baseline_runs, &base_runs, &head_runs};
  ComparePlan plan(context, m, base_runs, head_runs, io, request.ratio_rounds);

  ResultsDocument document = new_document(DocumentKind::compare, context, request.baseline);
  document.revisions = {base.record, head.record};
  const std::string opening = fmt::format(
      "comparing {} {} (base) with {} (head) against {} on suite {}: {}{}", context.adapter.name,
      request.base.short_sha, request.head.short_sha, request.baseline.version_line(),
      context.suite.name, count_text(m.scenes.size(), "scene"), shard_note(context));
  return measure_document(std::move(document), m, plan, opening, io);
}

}  // namespace raygate

#include "pipeline/measurement_plan.h"

namespace raygate {

// The defaults are a measurement that takes one pass and judges nothing beyond its ratios (the
// shape `run` has); each kind overrides what it decides.

RepeatChooser MeasurementPlan::repeats(const SuiteScene&) const { return {}; }

void MeasurementPlan::finish_scene(SceneResult&) {}

bool MeasurementPlan::revisits() const { return false; }

std::optional<StopRule> MeasurementPlan::revisit_stop(const SceneResult&, std::size_t, double) {
  return std::nullopt;
}

VisitPlan MeasurementPlan::plan_visit(const SceneResult&) const { return {}; }

void MeasurementPlan::rejudge(SceneResult&) {}

bool MeasurementPlan::wants_ratio_rounds(const SceneResult&) const { return false; }

std::optional<StopRule> MeasurementPlan::ratio_rounds_stop(const SceneResult&, std::size_t) {
  return std::nullopt;
}

void MeasurementPlan::rejudge_after_ratio_rounds(SceneResult&, std::size_t, const std::string&) {}

std::vector<std::string> MeasurementPlan::finish_suite(ResultsDocument&) { return {}; }

}  // namespace raygate

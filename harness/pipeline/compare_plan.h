// How `compare` (and bisect's steps) decide, as one plan (pipeline/measurement_plan.h): each
// scene's rounds stop once head's change against base is decided at the scene's share of the
// family (and a Monte Carlo image with it), within its share of the budget; the scenes left
// undecided get the budget's rest, the cheapest first; the scenes whose stored ratio is not yet
// within +-2% get ratio rounds (pipeline/stored_ratio.h); and Holm's control over the family
// judges the suite.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/image_stop.h"
#include "pipeline/measure_context.h"
#include "pipeline/measurement_estimate.h"
#include "pipeline/measurement_plan.h"
#include "pipeline/pipeline_io.h"
#include "pipeline/stop_rules.h"
#include "pipeline/suite_measurement.h"
#include "runner/contender.h"

namespace raygate {

// The family a compare's scenes share the false-alarm rate over: the whole selection, so a
// shard's scenes get the share they would have had in one job (docs/statistics.md §6c).
std::size_t compare_family_size(const MeasureContext& context, const SuiteMeasurement& m);

class ComparePlan final : public MeasurementPlan {
 public:
  // `m` and the contenders outlive the plan; `base` and `head` are re-run by --explain.
  // `ratio_rounds`: a stored ratio still imprecise gets ratio rounds (not in bisect's steps).
  ComparePlan(const MeasureContext& context, const SuiteMeasurement& m, const Contender& base,
              const Contender& head, PipelineIo& io, bool ratio_rounds = true);

  StopRule first_visit_stop(const SuiteScene& scene) override;
  RepeatChooser repeats(const SuiteScene& scene) const override;
  void finish_scene(SceneResult& scene) override;

  bool revisits() const override { return true; }
  std::optional<StopRule> revisit_stop(const SceneResult& scene, std::size_t scenes_left,
                                       double seconds_to_decide) override;
  VisitPlan plan_visit(const SceneResult& scene) const override;
  void rejudge(SceneResult& scene) override;

  bool wants_ratio_rounds(const SceneResult& scene) const override;
  std::optional<StopRule> ratio_rounds_stop(const SceneResult& scene,
                                            std::size_t scenes_left) override;
  void rejudge_after_ratio_rounds(SceneResult& scene, std::size_t rounds_before,
                                  const std::string& stop_reason) override;

  std::vector<std::string> finish_suite(ResultsDocument& document) override;

 private:
  // The change over the scene's first `change_rounds` rounds (all by default).
  void judge_change(SceneResult& scene, std::size_t change_rounds) const;
  StopRule scene_stop_rule(const StoppingPolicy& share, const std::string& scene_id) const;

  const MeasureContext& context_;
  const SuiteMeasurement& m_;
  const Contender& base_;
  const Contender& head_;
  PipelineIo& io_;
  std::size_t family_size_;
  double alpha_;  // each scene's share of the family's false-alarm rate
  SuiteBudget budget_;
  MeasurementEstimate estimate_;
  // A Monte Carlo image still inconclusive keeps its scene measuring (pipeline/image_stop.h).
  std::optional<NoisyImageFamily> noisy_images_;
  bool ratio_rounds_;
  // Why a scene's stored ratio stayed imprecise, by scene id, for the closing line.
  std::map<std::string, std::string> ratio_why_;
};

}  // namespace raygate

// How one kind of measurement decides: the questions measure_suite() asks while it measures the
// scenes, answered by one object per kind (`run`: pipeline/run_measurement.cpp, `compare`:
// pipeline/compare_plan.h). The loop owns the order of work (a first pass over the scenes, a
// second over the undecided ones when the measurement has a budget, a third for the stored
// ratios) and the plan owns every judgement: when a scene's rounds stop, how they repeat, what a
// finished scene's verdict is, and what the whole suite's is.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "results/results.h"
#include "runner/scheduler.h"
#include "runner/suite.h"

namespace raygate {

// The second pass's plan for a scene's next visit.
struct VisitPlan {
  // About how many seconds more the scene needs to decide; infinity when no number of rounds is
  // known to decide it (those go last).
  double seconds = std::numeric_limits<double>::infinity();
  // Runs of each contender per round in the visit, the fastest kept (ScheduleOptions::repeats):
  // 2 where each side's fastest of two is estimated to decide the scene sooner for its double
  // cost (measure/fastest_of_two.h); 0 keeps the measurement's own.
  std::size_t repeats = 0;
};

class MeasurementPlan {
 public:
  virtual ~MeasurementPlan() = default;

  // --- First pass: every scene in the suite's order.
  // The stopping rule of the scene's rounds.
  virtual StopRule first_visit_stop(const SuiteScene& scene) = 0;
  // How its rounds choose their runs per contender (runner/scheduler.h); empty: the schedule's.
  virtual RepeatChooser repeats(const SuiteScene& scene) const;
  // The scene's own judgement once measured without failure, after its ratios and golden
  // checks (compare: the change and head's image against base's).
  virtual void finish_scene(SceneResult& scene);

  // --- Second pass (only under a whole-measurement budget): the scenes left undecided when
  // their share of the time ran out get more rounds (pipeline/suite_measurement.cpp).
  virtual bool revisits() const;
  // The stopping rule of a scene's further rounds, given about how many seconds more it needs;
  // `scenes_left` counts it and the undecided scenes after it. nullopt: no time is left for it.
  virtual std::optional<StopRule> revisit_stop(const SceneResult& scene, std::size_t scenes_left,
                                               double seconds_to_decide);
  // What the scene's next visit needs, and how it runs.
  virtual VisitPlan plan_visit(const SceneResult& scene) const;
  // The scene's judgement again, over all its rounds (its image checks stay the first visit's).
  virtual void rejudge(SceneResult& scene);

  // --- Third pass: rounds the baseline joins, for a stored ratio precise enough to trend
  // (pipeline/stored_ratio.h). They never change a decided verdict.
  virtual bool wants_ratio_rounds(const SceneResult& scene) const;
  // Their stopping rule; `scenes_left` counts the scene and those after it that want them.
  // nullopt: no time is left for it.
  virtual std::optional<StopRule> ratio_rounds_stop(const SceneResult& scene,
                                                    std::size_t scenes_left);
  // The scene's summaries after its ratio rounds; `rounds_before` the rounds it had before them
  // and `stop_reason` why those stopped (runner/scheduler.h, SceneRuns::stop_reason).
  virtual void rejudge_after_ratio_rounds(SceneResult& scene, std::size_t rounds_before,
                                          const std::string& stop_reason);

  // --- Once every scene is measured, before the complete document is written: judgements
  // across scenes (compare: Holm over the family). Returns lines for the measurement's account.
  virtual std::vector<std::string> finish_suite(ResultsDocument& document);
};

}  // namespace raygate

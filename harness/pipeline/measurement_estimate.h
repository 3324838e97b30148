// How long a run or compare will take, and whether its budget (--max-minutes) can decide it,
// said before the rounds go on (issue 39): from the first round of the first scene (what each
// program's run costs here, and the scheduler's overhead around them) and the fewest rounds a
// verdict needs; then again once the first scene is decided, from the rounds it took; and again
// whenever the scenes measured since put it off by more than 30%. When the
// budget cannot decide the suite, it says what would: a longer budget, shards of a CI matrix
// (--shard K/N, docs/shards.md), or a suite calibrated to shorter renders (raygate calibrate).
// Pure arithmetic in estimate_measurement(); MeasurementEstimate watches a scene's stop rule.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/measure_context.h"
#include "pipeline/pipeline_io.h"
#include "runner/scheduler.h"

namespace raygate {

// What one round of a scene costs, in wall seconds of its runs.
struct RoundCost {
  double normalizer_seconds = 0.0;  // the baseline's run
  double tracers_seconds = 0.0;     // the other contenders' runs together
  // Wall time of the scheduler's work around the runs (starting processes, reading images),
  // as a factor on the runs' own seconds: 1 = none.
  double overhead_factor = 1.0;
};

// What the measurement is: how many scenes, how the schedule runs them, and its budget.
struct EstimateShape {
  std::size_t scenes = 0;
  int warmup_runs = 1;                // per contender, every scene
  std::size_t normalizer_rounds = 0;  // rounds the baseline joins; 0 = every round
  double budget_seconds = 0.0;        // --max-minutes in seconds; 0 = none
  double scene_max_seconds = 0.0;     // --max-seconds; 0 = none
  std::string command = "compare";    // for the advice's command lines
};

struct Estimate {
  std::size_t rounds_per_scene = 0;
  double seconds_per_scene = 0.0;
  double total_seconds = 0.0;
  bool fits_budget = true;       // within budget_seconds (always, with no budget)
  bool fits_scene_limit = true;  // a scene's estimate within --max-seconds
  // With a budget it does not fit: the fewest shards, each given the same budget, that would
  // (the family of a shard stays the whole suite, so its scenes need the same rounds).
  std::size_t shards_needed = 1;
  // The tracer's seconds per render that would fit the budget at these rounds (for calibrate);
  // 0 when it fits, or when no render time would (the baseline alone does not fit).
  double tracer_render_seconds_to_fit = 0.0;
};

// Seconds of one scene measured `rounds` rounds at `cost`: warm-ups of every contender, the
// baseline's rounds, the others' rounds, times the overhead factor.
double scene_seconds(const RoundCost& cost, const EstimateShape& shape, std::size_t rounds);

// The measurement estimated as `shape.scenes` scenes like this one, each `rounds` rounds.
// `tracer_count`: how many tracer runs a round holds (1 for run, 2 for compare), to say what one
// render of the tracer would need to cost.
Estimate estimate_measurement(const RoundCost& cost, const EstimateShape& shape, std::size_t rounds,
                              std::size_t tracer_count);

// The measurement estimated from the first-pass seconds of the scenes measured so far: their mean
// for each of `shape.scenes`. `render_seconds`: one tracer run's, for the calibrate advice.
Estimate estimate_from_scenes(const std::vector<double>& scene_seconds, const EstimateShape& shape,
                              double render_seconds);

// The estimate as lines for the measurement's account, starting with `basis` (what it is
// measured from) and saying what would decide the suite when the budget cannot.
std::vector<std::string> estimate_lines(const Estimate& estimate, const EstimateShape& shape,
                                        const std::string& basis);

// The cost of a round from its runs and the scheduler's seconds so far (warm-ups included).
RoundCost round_cost(const Round& round, double seconds_spent, int warmup_runs);

// The shape of a measurement of `scenes` scenes under `context` (its schedule and budget), by
// `command` ("run", "compare").
EstimateShape estimate_shape(const MeasureContext& context, std::size_t scenes,
                             const std::string& command);

// The fewest rounds a compare scene can be decided in: the fewest its confidence sequences are
// bounded in, at the family's level `decision_alpha` (REGRESSED) or a scene's significance
// (UNCHANGED), and never fewer than --min-rounds; 2 when counted (sim mode).
std::size_t fewest_compare_rounds(const MeasureContext& context, double decision_alpha);

// Watches the first visit of each scene through its stop rule and says the estimate: after the
// first scene's first round (at the fewest rounds a verdict needs: a floor, said as one), once the
// first scene stops (at the rounds it took, if it was decided), and again after a later scene
// whenever the scenes so far put the last estimate off by more than 30%.
class MeasurementEstimate {
 public:
  // `fewest_rounds`: the fewest rounds any verdict of this measurement needs. `tracer_count`: as
  // for estimate_measurement.
  MeasurementEstimate(EstimateShape shape, std::size_t fewest_rounds, std::size_t tracer_count,
                      ProgressSink& progress);

  // `rule` for the first visit of the scene `scene_id`.
  StopRule watch(StopRule rule, const std::string& scene_id);

 private:
  void first_round(const std::vector<Round>& rounds, double seconds_spent);
  void first_scene_done(const std::vector<Round>& rounds, double seconds_spent,
                        StopDecision decision);
  void scene_done(double seconds_spent, StopDecision decision);

  EstimateShape shape_;
  std::size_t fewest_rounds_;
  std::size_t tracer_count_;
  ProgressSink& progress_;
  std::size_t scenes_watched_ = 0;
  std::string first_scene_;
  std::optional<RoundCost> cost_;
  std::vector<double> scene_seconds_;  // each watched scene's first visit, in the order measured
  std::size_t undecided_ = 0;          // of those, stopped without a verdict
  double said_total_seconds_ = 0.0;    // the total last said; 0 before the first scene stops
};

}  // namespace raygate

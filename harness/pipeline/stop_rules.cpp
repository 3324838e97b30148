#include "pipeline/stop_rules.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "measure/compare_budget.h"

namespace raygate {

StopRule stop_rule(const StoppingPolicy& policy, SceneVerdict verdict) {
  return [policy, verdict = std::move(verdict)](const std::vector<Round>& rounds,
                                                double seconds_spent) {
    return should_stop({rounds.size(), seconds_spent, verdict(rounds)}, policy);
  };
}

SceneVerdict ratio_verdict(const StoppingPolicy& policy, Role tracer_role, Role baseline_role) {
  return [=](const std::vector<Round>& rounds) {
    return ratio_decided(round_samples(rounds, tracer_role, baseline_role), policy);
  };
}

SequenceLevels scene_levels(const ScenePolicy& scene, double decision_alpha) {
  SequenceLevels levels;
  levels.decision_alpha = decision_alpha;
  levels.equivalence_alpha = scene.significance;
  levels.one_look_confidence = 1.0 - scene.significance;
  return levels;
}

SceneVerdict change_verdict(const StoppingPolicy& policy, const ScenePolicy& scene,
                            const SequenceLevels& levels, bool counted) {
  const BootstrapOptions options = change_bootstrap(scene);
  const double max_slowdown = scene.max_slowdown;
  return [=](const std::vector<Round>& rounds) {
    return change_decided(compare_samples(rounds), policy, max_slowdown, options, levels, counted);
  };
}

StopRule ratio_stop_rule(const StoppingPolicy& policy, Role tracer_role, Role baseline_role) {
  return stop_rule(policy, ratio_verdict(policy, tracer_role, baseline_role));
}

StopRule change_stop_rule(const StoppingPolicy& policy, const ScenePolicy& scene,
                          const SequenceLevels& levels, bool counted) {
  return stop_rule(policy, change_verdict(policy, scene, levels, counted));
}

BootstrapOptions change_bootstrap(const ScenePolicy& scene) {
  BootstrapOptions options;
  options.confidence = 1.0 - scene.significance;
  return options;
}

SuiteBudget::SuiteBudget(const StoppingPolicy& policy, std::size_t scenes, Clock& clock,
                         std::size_t reserve_scenes)
    : policy_(policy),
      scenes_left_(scenes),
      reserve_scenes_(reserve_scenes),
      clock_(clock),
      started_(clock.now_seconds()) {}

StoppingPolicy SuiteBudget::next_scene() {
  StoppingPolicy scene = policy_;
  const double share = scene_time_share(60.0 * policy_.max_minutes, clock_.now_seconds() - started_,
                                        std::max<std::size_t>(scenes_left_, 1) + reserve_scenes_);
  scene.max_seconds = std::min(scene.max_seconds, share);
  if (scenes_left_ > 0) --scenes_left_;
  return scene;
}

StoppingPolicy SuiteBudget::again(double seconds_spent, std::size_t scenes_left,
                                  double seconds_to_decide) const {
  StoppingPolicy scene = policy_;
  const double budget = 60.0 * policy_.max_minutes;
  const double elapsed = clock_.now_seconds() - started_;
  const double left = scene_time_share(budget, elapsed, 1);
  const double share =
      std::isfinite(seconds_to_decide)
          ? std::min(left, kRevisitMargin * seconds_to_decide)
          : scene_time_share(budget, elapsed, std::max<std::size_t>(scenes_left, 1));
  scene.max_seconds = std::min(scene.max_seconds, seconds_spent + share);
  return scene;
}

std::size_t revisit_reserve_scenes(std::size_t scenes) {
  return scenes <= 1 ? 0 : (scenes + 3) / 4;
}

}  // namespace raygate

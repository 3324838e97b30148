#include "pipeline/stopping.h"

#include <utility>

namespace raygate {

StopRule stop_rule(const StoppingPolicy& policy, SceneVerdict verdict) {
  return [policy, verdict = std::move(verdict)](const std::vector<Round>& rounds,
                                                double seconds_spent) {
    return should_stop({rounds.size(), seconds_spent, verdict(rounds)}, policy);
  };
}

SceneVerdict ratio_verdict(const StoppingPolicy& policy, const std::string& tracer_role,
                           const std::string& baseline_role) {
  return [=](const std::vector<Round>& rounds) {
    return ratio_decided(round_samples(rounds, tracer_role, baseline_role), policy);
  };
}

SceneVerdict change_verdict(const StoppingPolicy& policy, const ScenePolicy& scene,
                            bool counted) {
  const BootstrapOptions options = change_bootstrap(scene);
  const double max_slowdown = scene.max_slowdown;
  return [=](const std::vector<Round>& rounds) {
    return change_decided(compare_samples(rounds), policy, max_slowdown, options, counted);
  };
}

StopRule ratio_stop_rule(const StoppingPolicy& policy, const std::string& tracer_role,
                         const std::string& baseline_role) {
  return stop_rule(policy, ratio_verdict(policy, tracer_role, baseline_role));
}

StopRule change_stop_rule(const StoppingPolicy& policy, const ScenePolicy& scene,
                          bool counted) {
  return stop_rule(policy, change_verdict(policy, scene, counted));
}

BootstrapOptions change_bootstrap(const ScenePolicy& scene) {
  BootstrapOptions options;
  options.confidence = 1.0 - scene.significance;
  return options;
}

}  // namespace raygate

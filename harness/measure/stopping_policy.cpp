#include "measure/stopping_policy.h"

#include "measure/simulated_cost.h"

#include <algorithm>
#include <limits>

namespace raygate {

std::string_view to_string(StopDecision decision) {
  switch (decision) {
    case StopDecision::continue_measuring: return "continue";
    case StopDecision::stop_converged: return "stop_converged";
    case StopDecision::stop_budget_rounds: return "stop_budget_rounds";
    case StopDecision::stop_budget_time: return "stop_budget_time";
  }
  return "unknown";
}

StopDecision should_stop(const StoppingState& state, const StoppingPolicy& policy) {
  if (state.decided) return StopDecision::stop_converged;
  if (state.rounds >= policy.max_rounds) return StopDecision::stop_budget_rounds;
  if (state.seconds_spent >= policy.max_seconds) return StopDecision::stop_budget_time;
  return StopDecision::continue_measuring;
}

StoppingPolicy change_stopping_policy() {
  StoppingPolicy policy;
  policy.max_rounds = 300;
  policy.max_minutes = 8.0;
  return policy;
}

double budgeted_run_seconds(const StoppingPolicy& policy, double own_seconds) {
  double seconds = own_seconds;
  if (policy.max_seconds > 0.0) seconds = std::min(seconds, policy.max_seconds);
  if (policy.max_minutes > 0.0) seconds = std::min(seconds, 60.0 * policy.max_minutes);
  return std::max(seconds, 1.0);  // a run needs some time to exist at all
}

std::size_t rounds_to_decide(const StoppingPolicy& policy) {
  return std::max<std::size_t>(policy.min_rounds, 2);
}

bool ratio_decided(std::span<const RoundSample> rounds, const StoppingPolicy& policy,
                   const BootstrapOptions& options) {
  if (rounds.size() < rounds_to_decide(policy)) return false;
  return summarize_ratio(rounds, options.confidence).relative_half_width <=
         policy.target_relative_half_width;
}

bool change_decided(std::span<const CompareRound> rounds, const StoppingPolicy& policy,
                    double max_slowdown, const BootstrapOptions& options,
                    const SequenceLevels& levels, bool counted) {
  if (rounds.size() < rounds_to_decide(policy)) return false;
  return classify_change(measured_change(rounds, options, counted, levels), max_slowdown) !=
         ChangeVerdict::inconclusive;
}

StopDecision decide_stopping(std::size_t rounds, double relative_half_width,
                             const StoppingPolicy& policy, double seconds_spent) {
  const bool decided = rounds >= policy.min_rounds && rounds > 0 &&
                       relative_half_width <= policy.target_relative_half_width;
  return should_stop({rounds, seconds_spent, decided}, policy);
}

StopDecision decide_stopping(std::span<const RoundSample> rounds, const StoppingPolicy& policy,
                             double seconds_spent, const BootstrapOptions& options) {
  // No CI is computed below min_rounds: with one round it would be a point and "converge".
  double relative_half_width = std::numeric_limits<double>::infinity();
  if (!rounds.empty() && rounds.size() >= policy.min_rounds) {
    relative_half_width = summarize_ratio(rounds, options.confidence).relative_half_width;
  }
  return decide_stopping(rounds.size(), relative_half_width, policy, seconds_spent);
}

}  // namespace raygate

#include "measure/stopping.h"

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

StopDecision decide_stopping(std::size_t rounds, double relative_half_width,
                             const StoppingPolicy& policy, double seconds_spent) {
  if (rounds >= policy.min_rounds && rounds > 0 &&
      relative_half_width <= policy.target_relative_half_width) {
    return StopDecision::stop_converged;
  }
  if (rounds >= policy.max_rounds) return StopDecision::stop_budget_rounds;
  if (seconds_spent >= policy.max_seconds) return StopDecision::stop_budget_time;
  return StopDecision::continue_measuring;
}

StopDecision decide_stopping(std::span<const RoundSample> rounds, const StoppingPolicy& policy,
                             double seconds_spent, const BootstrapOptions& options) {
  // No CI is computed below min_rounds: with one round it would be a point and "converge".
  double relative_half_width = std::numeric_limits<double>::infinity();
  if (!rounds.empty() && rounds.size() >= policy.min_rounds) {
    relative_half_width = summarize_ratio(rounds, options).relative_half_width;
  }
  return decide_stopping(rounds.size(), relative_half_width, policy, seconds_spent);
}

}  // namespace raygate

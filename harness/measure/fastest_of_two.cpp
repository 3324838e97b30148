#include "measure/fastest_of_two.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "measure/descriptive.h"

namespace raygate {

double quartile_spread(std::span<const double> log_changes) {
  // Phi^-1(3/4): the upper quartile of a normal lies this many sigmas above its median.
  constexpr double kQuartileSigmas = 0.6744897501960817;
  const double centre = median(log_changes);
  const double below = centre - quantile(log_changes, 0.25);
  const double above = quantile(log_changes, 0.75) - centre;
  return std::max(below, above) / kQuartileSigmas;
}

std::optional<double> fastest_of_two_spread(std::span<const CompareRound> one_run_rounds) {
  const std::size_t pairs = one_run_rounds.size() / 2;
  if (pairs < kMinPairsForSpread) return std::nullopt;
  std::vector<double> log_changes;
  log_changes.reserve(pairs);
  for (std::size_t k = 0; k < pairs; ++k) {
    const CompareRound& first = one_run_rounds[2 * k];
    const CompareRound& second = one_run_rounds[2 * k + 1];
    const double base = std::min(first.base_seconds, second.base_seconds);
    const double head = std::min(first.head_seconds, second.head_seconds);
    if (!(base > 0.0 && head > 0.0)) return std::nullopt;
    log_changes.push_back(std::log(head / base));
  }
  return quartile_spread(log_changes);
}

}  // namespace raygate

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

namespace {

// Seconds of a round as (numerator, denominator) of the log the verdict judges.
struct RoundSeconds {
  double numerator = 0.0;
  double denominator = 0.0;
};

RoundSeconds seconds_of(const CompareRound& round) {
  return {round.head_seconds, round.base_seconds};
}

RoundSeconds seconds_of(const RoundSample& round) {
  return {round.tracer_seconds, round.baseline_seconds};
}

template <typename RoundT>
std::optional<double> spread_of_pairs(std::span<const RoundT> one_run_rounds) {
  const std::size_t pairs = one_run_rounds.size() / 2;
  if (pairs < kMinPairsForSpread) return std::nullopt;
  std::vector<double> log_values;
  log_values.reserve(pairs);
  for (std::size_t k = 0; k < pairs; ++k) {
    const RoundSeconds first = seconds_of(one_run_rounds[2 * k]);
    const RoundSeconds second = seconds_of(one_run_rounds[2 * k + 1]);
    const double numerator = std::min(first.numerator, second.numerator);
    const double denominator = std::min(first.denominator, second.denominator);
    if (!(numerator > 0.0 && denominator > 0.0)) return std::nullopt;
    log_values.push_back(std::log(numerator / denominator));
  }
  return quartile_spread(log_values);
}

}  // namespace

std::optional<double> fastest_of_two_spread(std::span<const CompareRound> one_run_rounds) {
  return spread_of_pairs(one_run_rounds);
}

std::optional<double> fastest_of_two_spread(std::span<const RoundSample> one_run_rounds) {
  return spread_of_pairs(one_run_rounds);
}

bool fastest_of_two_pays(double one_run_spread, double fastest_of_two_spread) {
  // Strictly: rounds without spread (sim mode's counts) have nothing to gain.
  return 2.0 * fastest_of_two_spread * fastest_of_two_spread <
         kFastestOfTwoMustSave * one_run_spread * one_run_spread;
}

}  // namespace raygate

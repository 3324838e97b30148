#include "measure/ratio.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "core/error.h"
#include "measure/descriptive.h"
#include "measure/median_interval.h"

namespace raygate {
namespace {

void require_time(double seconds, std::size_t round, const char* which) {
  if (!(seconds > 0.0) || !std::isfinite(seconds)) {
    throw InfraError(
        fmt::format("round {}: {} time {} s is not a positive number; cannot "
                    "normalize (check the timing source of the adapter)",
                    round + 1, which, seconds));
  }
}

std::vector<double> field(std::span<const RoundSample> rounds, double RoundSample::*member) {
  std::vector<double> values;
  values.reserve(rounds.size());
  for (const RoundSample& r : rounds) values.push_back(r.*member);
  return values;
}

// The distribution-free interval of the median log-ratio at `confidence`; below the rounds it
// needs (6 at 95%), the range of the rounds, which covers with 1 - 2^(1-n) only. Not the
// bootstrap: `run` stops at the first round whose interval is narrow enough, and at that round
// the bootstrap's "95%" covered 86-90% in simulation (docs/statistics.md §3).
Interval log_ratio_interval(std::span<const double> logs, double confidence) {
  if (std::optional<Interval> interval = median_interval(logs, confidence)) return *interval;
  const auto [lowest, highest] = std::minmax_element(logs.begin(), logs.end());
  return {*lowest, *highest};
}

}  // namespace

std::vector<double> log_ratios(std::span<const RoundSample> rounds) {
  std::vector<double> logs;
  logs.reserve(rounds.size());
  for (std::size_t i = 0; i < rounds.size(); ++i) {
    require_time(rounds[i].tracer_seconds, i, "tracer");
    require_time(rounds[i].baseline_seconds, i, "baseline");
    logs.push_back(std::log(rounds[i].tracer_seconds / rounds[i].baseline_seconds));
  }
  return logs;
}

RatioSummary summarize_ratio(std::span<const RoundSample> rounds, double confidence) {
  if (rounds.empty()) throw std::invalid_argument("summarize_ratio: no rounds");
  const std::vector<double> logs = log_ratios(rounds);
  const Interval log_interval = log_ratio_interval(logs, confidence);

  RatioSummary summary;
  summary.rounds = rounds.size();
  summary.log_ratio_median = median(logs);
  summary.ratio = std::exp(summary.log_ratio_median);
  // exp is monotone, so an interval of order statistics maps across unchanged.
  summary.ratio_interval = {std::exp(log_interval.lower), std::exp(log_interval.upper)};
  summary.relative_half_width = summary.ratio_interval.width() / 2.0 / summary.ratio;
  summary.log_ratio_mad_scaled = mad_scaled(logs);
  summary.tracer_median_seconds = median(field(rounds, &RoundSample::tracer_seconds));
  summary.baseline_median_seconds = median(field(rounds, &RoundSample::baseline_seconds));
  return summary;
}

SuiteScore suite_score(std::span<const std::vector<RoundSample>> scenes,
                       const BootstrapOptions& options) {
  if (scenes.empty()) throw std::invalid_argument("suite_score: no scenes");
  if (options.resamples < 1) throw std::invalid_argument("suite_score: resamples must be >= 1");
  Xoshiro256 rng(options.seed);
  const auto replicate_count = static_cast<std::size_t>(options.resamples);
  std::vector<double> replicate_log_sums(replicate_count, 0.0);
  double point_log_sum = 0.0;
  for (const std::vector<RoundSample>& rounds : scenes) {
    if (rounds.empty()) throw std::invalid_argument("suite_score: a scene has no rounds");
    const std::vector<double> logs = log_ratios(rounds);
    point_log_sum += median(logs);
    const std::vector<double> replicates =
        bootstrap_median_replicates(logs, options.resamples, rng);
    for (std::size_t b = 0; b < replicate_count; ++b) replicate_log_sums[b] += replicates[b];
  }
  const auto scene_count = static_cast<double>(scenes.size());
  std::vector<double> replicate_scores;
  replicate_scores.reserve(replicate_count);
  for (double log_sum : replicate_log_sums) replicate_scores.push_back(log_sum / scene_count);
  const Interval log_interval =
      percentile_interval(std::move(replicate_scores), options.confidence);

  SuiteScore score;
  score.scenes = scenes.size();
  score.score = std::exp(point_log_sum / scene_count);
  score.interval = {std::exp(log_interval.lower), std::exp(log_interval.upper)};
  return score;
}

}  // namespace raygate

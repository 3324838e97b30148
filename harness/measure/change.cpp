#include "measure/change.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <vector>

#include "measure/descriptive.h"
#include "measure/median_interval.h"

namespace raygate {
namespace {

std::vector<RoundSample> against_baseline(std::span<const CompareRound> rounds,
                                          double CompareRound::*revision) {
  std::vector<RoundSample> samples;
  samples.reserve(rounds.size());
  for (const CompareRound& r : rounds) samples.push_back({r.*revision, r.baseline_seconds});
  return samples;
}

}  // namespace

ChangeSummary summarize_change(std::span<const CompareRound> rounds,
                               const BootstrapOptions& options) {
  if (rounds.empty()) throw std::invalid_argument("summarize_change: no rounds");
  const std::vector<RoundSample> base_rounds = against_baseline(rounds, &CompareRound::base_seconds);
  const std::vector<RoundSample> head_rounds = against_baseline(rounds, &CompareRound::head_seconds);
  // log_ratios validates every time; ln(head/base) = ln(head/baseline) - ln(base/baseline).
  const std::vector<double> base_logs = log_ratios(base_rounds);
  const std::vector<double> head_logs = log_ratios(head_rounds);
  std::vector<double> log_changes;
  log_changes.reserve(rounds.size());
  for (const CompareRound& r : rounds) log_changes.push_back(std::log(r.head_seconds / r.base_seconds));

  ChangeSummary summary;
  summary.rounds = rounds.size();
  summary.log_change_median = median(log_changes);
  summary.change = std::expm1(summary.log_change_median);
  summary.confidence = options.confidence;
  // Too few rounds for the interval: report the observed range, which classify_change will not
  // decide on.
  const std::optional<Interval> at_confidence = median_interval(log_changes, options.confidence);
  const auto [lowest, highest] = std::minmax_element(log_changes.begin(), log_changes.end());
  const Interval log_interval = at_confidence.value_or(Interval{*lowest, *highest});
  summary.change_interval = {std::expm1(log_interval.lower), std::expm1(log_interval.upper)};
  summary.log_change_mad_scaled = mad_scaled(log_changes);
  summary.base = summarize_ratio(base_rounds, options);
  summary.head = summarize_ratio(head_rounds, options);
  // Ranks are unchanged by exp, so testing the log-ratios is testing the ratios.
  summary.mann_whitney = mann_whitney_u(head_logs, base_logs);
  return summary;
}

std::string_view to_string(ChangeVerdict verdict) {
  switch (verdict) {
    case ChangeVerdict::unchanged: return "UNCHANGED";
    case ChangeVerdict::improved: return "IMPROVED";
    case ChangeVerdict::regressed: return "REGRESSED";
    case ChangeVerdict::inconclusive: return "INCONCLUSIVE";
  }
  return "UNKNOWN";
}

ChangeVerdict classify_change(double change, const Interval& change_interval, double threshold) {
  if (!(threshold >= 0.0)) throw std::invalid_argument("classify_change: negative threshold");
  // The point estimate is trusted against the limit only when it is precise to within the
  // limit; a wider interval decides only when it clears the limit entirely.
  const bool precise = change_interval.upper - change_interval.lower <= 2.0 * threshold;
  if (change_interval.lower > 0.0 && change > threshold &&
      (precise || change_interval.lower > threshold)) {
    return ChangeVerdict::regressed;
  }
  if (change_interval.upper < 0.0 && change < -threshold &&
      (precise || change_interval.upper < -threshold)) {
    return ChangeVerdict::improved;
  }
  if (change_interval.lower >= -threshold && change_interval.upper <= threshold) {
    return ChangeVerdict::unchanged;
  }
  return ChangeVerdict::inconclusive;
}

ChangeVerdict classify_change(const ChangeSummary& summary, double threshold) {
  if (!summary.exact && summary.rounds < min_values_for_median_interval(summary.confidence)) {
    return ChangeVerdict::inconclusive;
  }
  return classify_change(summary.change, summary.change_interval, threshold);
}

}  // namespace raygate

// The performance change between two revisions measured in the same rounds, each round running
// baseline, base and head in rotating order (DESIGN.md §6), and the verdict on that change.
// Within one round ratio_head / ratio_base = t_head / t_base: the baseline cancels. It is still
// measured because it normalizes across jobs and machines (history, shards of a CI matrix), and
// each revision's own normalized ratio is reported and stored.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

#include "measure/bootstrap.h"
#include "measure/mann_whitney.h"
#include "measure/ratio.h"

namespace raygate {

struct CompareRound {
  double baseline_seconds = 0.0;
  double base_seconds = 0.0;
  double head_seconds = 0.0;
};

struct ChangeSummary {
  std::size_t rounds = 0;
  double change = 0.0;  // exp(median of per-round ln(t_head / t_base)) - 1; +0.05 = 5% slower
  // The distribution-free order-statistic interval of the median (measure/median_interval.h) at
  // `confidence`, same units as `change`. With too few rounds to reach that confidence it is the
  // whole observed range, and no verdict but INCONCLUSIVE may be drawn from it.
  Interval change_interval;
  double confidence = 0.95;
  double log_change_median = 0.0;
  double log_change_mad_scaled = 0.0;
  RatioSummary base;  // each revision's normalized ratio against the baseline
  RatioSummary head;
  MannWhitneyResult mann_whitney;  // a = head's per-round ratios, b = base's
  // Counted, not sampled (--timing sim, measure/simulated_cost.h): every run of each contender
  // cost exactly the same, so `change` is exact and its interval a point, however few rounds.
  bool exact = false;
};

// Throws std::invalid_argument for no rounds, InfraError for a time that is not positive.
ChangeSummary summarize_change(std::span<const CompareRound> rounds,
                               const BootstrapOptions& options = {});

enum class ChangeVerdict { unchanged, improved, regressed, inconclusive };

std::string_view to_string(ChangeVerdict verdict);

inline constexpr double kDefaultChangeThreshold = 0.03;

// The rule (docs/statistics.md §6): REGRESSED when the CI lies above 0, the point estimate is
// above +threshold, and either the CI is no wider than 2 x threshold or it lies wholly above
// +threshold; IMPROVED mirrors it; UNCHANGED when the whole CI lies within [-threshold,
// +threshold]; otherwise INCONCLUSIVE.
ChangeVerdict classify_change(double change, const Interval& change_interval,
                              double threshold = kDefaultChangeThreshold);

// The rule above, and INCONCLUSIVE whatever the numbers while there are fewer rounds than an
// interval at the summary's confidence needs (6 at 95%), unless the summary is exact.
ChangeVerdict classify_change(const ChangeSummary& summary,
                              double threshold = kDefaultChangeThreshold);

}  // namespace raygate

// The performance change between two revisions measured in the same rounds, each round running
// baseline, base and head in rotating order (DESIGN.md §6), and the verdict on that change.
// Within one round ratio_head / ratio_base = t_head / t_base: the baseline cancels. It is still
// measured because it normalizes across jobs and machines (history, shards of a CI matrix), and
// each revision's own normalized ratio is reported and stored.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "measure/bootstrap.h"
#include "measure/mann_whitney.h"
#include "measure/ratio.h"

namespace raygate {

struct CompareRound {
  // Empty in rounds the baseline did not join (ScheduleOptions::normalizer_rounds): the change
  // needs only base and head, the normalized ratios only the rounds with a baseline.
  std::optional<double> baseline_seconds;
  double base_seconds = 0.0;
  double head_seconds = 0.0;
};

// Which interval the change carries: the fixed-n order-statistic interval (one look), or the
// anytime-valid confidence sequence (any number of looks; what compare decides on).
enum class ChangeIntervalKind { order_statistic, confidence_sequence };

std::string_view to_string(ChangeIntervalKind kind);
// "order-statistic" or "confidence-sequence"; nullopt for anything else.
std::optional<ChangeIntervalKind> change_interval_kind(std::string_view text);

struct ChangeSummary {
  std::size_t rounds = 0;
  double change = 0.0;  // exp(median of per-round ln(t_head / t_base)) - 1; +0.05 = 5% slower
  // The interval of the median at `confidence`, same units as `change`: the anytime-valid
  // confidence sequence compare decides on (interval_kind), or in documents from before it the
  // distribution-free order-statistic interval (measure/median_interval.h). With too few rounds
  // to reach that confidence it is the whole observed range, and no verdict but INCONCLUSIVE may
  // be drawn from it.
  Interval change_interval;
  double confidence = 0.95;
  ChangeIntervalKind interval_kind = ChangeIntervalKind::order_statistic;
  // Confidence sequences only (docs/statistics.md §6): the wider-level sequence that UNCHANGED
  // must fit in, and the one-look order-statistic interval that says whether the point estimate
  // is precise. Each is the observed range while it is unbounded (too few rounds).
  Interval equivalence_interval;
  double equivalence_confidence = 0.0;
  Interval one_look_interval;
  double one_look_confidence = 0.0;
  double log_change_median = 0.0;
  double log_change_mad_scaled = 0.0;
  // Each revision's normalized ratio against the baseline (default-constructed, 0 rounds, when
  // it joined no round): base's over the rounds the baseline joined; head's is base's times the
  // change (ratio_through_change), so the two ratios and the change agree in sign and size.
  RatioSummary base;
  RatioSummary head;
  MannWhitneyResult mann_whitney;  // a = head's per-round ratios, b = base's
  // Counted, not sampled (--timing sim, measure/simulated_cost.h): each contender's runs cost the
  // same (or within 0.25%): `change` is counted, its interval a point (or the runs' extremes).
  bool exact = false;
};

// The levels of the sequential rule, each alpha the chance of one side's error at any round.
struct SequenceLevels {
  double decision_alpha = 0.01;       // REGRESSED / IMPROVED: the scene's share of the family's
  double equivalence_alpha = 0.05;    // UNCHANGED: the chance a change beyond the limit is missed
  double one_look_confidence = 0.95;  // precision of the point estimate (not an error rate)
};

// With `sequence`, change_interval is the confidence sequence at decision_alpha
// (measure/confidence_sequence.h), confidence = 1 - 2 decision_alpha, and the equivalence and
// one-look intervals are filled in; the ratios keep `options`. Without it, the one-look
// order-statistic interval at options.confidence. Throws std::invalid_argument for no rounds,
// InfraError for a time that is not positive.
ChangeSummary summarize_change(std::span<const CompareRound> rounds,
                               const BootstrapOptions& options = {},
                               const std::optional<SequenceLevels>& sequence = std::nullopt);

// head's normalized ratio as base's ratio times the change: t_head / t_baseline = (t_base /
// t_baseline) (t_head / t_base), each factor by its own median. The baseline joins only a few
// rounds (ScheduleOptions::normalizer_rounds), and the median of head/baseline over those few
// can disagree in sign with the change measured in every round. The interval is base's scaled
// by the change (the change is the far tighter of the two); head's own times (rounds, median
// seconds, spread) are kept from `head_own`.
RatioSummary ratio_through_change(const RatioSummary& base, const RatioSummary& head_own,
                                  double change);

// ln(t_head / t_base) of each round, in order. Throws InfraError for a time that is not
// positive and finite.
std::vector<double> compare_log_changes(std::span<const CompareRound> rounds);

// The sequential rule's inputs: the change and its three intervals, nullopt while unbounded.
struct SequentialIntervals {
  double change = 0.0;
  std::optional<Interval> decision;
  std::optional<Interval> equivalence;
  std::optional<Interval> one_look;
};

// The same intervals from per-round ln(t_head / t_base), in measurement order (non-empty).
SequentialIntervals sequential_intervals(std::span<const double> log_changes,
                                         const SequenceLevels& levels);

enum class ChangeVerdict { unchanged, improved, regressed, inconclusive };

std::string_view to_string(ChangeVerdict verdict);
// The verdict a word names ("UNCHANGED", ...); nullopt for any other word.
std::optional<ChangeVerdict> change_verdict_named(std::string_view word);

inline constexpr double kDefaultChangeThreshold = 0.03;

// The rule (docs/statistics.md §6): REGRESSED when the CI lies above 0, the point estimate is
// above +threshold, and either the CI is no wider than 2 x threshold or it lies wholly above
// +threshold; IMPROVED mirrors it; UNCHANGED when the whole CI lies within [-threshold,
// +threshold]; otherwise INCONCLUSIVE.
ChangeVerdict classify_change(double change, const Interval& change_interval,
                              double threshold = kDefaultChangeThreshold);

// The sequential rule (docs/statistics.md §6): REGRESSED when the decision interval lies above
// 0, the point estimate is above +threshold, and either the one-look interval is no wider than
// 2 x threshold or the decision interval lies wholly above +threshold; IMPROVED mirrors it;
// UNCHANGED when the equivalence interval lies within +-threshold; INCONCLUSIVE otherwise and
// while an interval it needs is unbounded.
ChangeVerdict classify_sequential(const SequentialIntervals& intervals, double threshold);

// By the summary: an exact summary (sim mode) judged by its change alone; else by its interval
// kind, the one-look rule above (INCONCLUSIVE below the rounds its interval needs, 6 at 95%) or
// the sequential rule on the stored intervals.
ChangeVerdict classify_change(const ChangeSummary& summary,
                              double threshold = kDefaultChangeThreshold);

// About how many rounds in all an INCONCLUSIVE scene would need if its rounds go on as they
// went: the first round count at which the interval its nearer verdict needs (UNCHANGED: the
// equivalence sequence within +-threshold; REGRESSED or IMPROVED: the decision sequence clear of
// 0, and precise) is projected to hold. The projection puts the sequence's ends, whose ranks
// depend on the round count alone, where those ranks fall for rounds spread normally with the
// rounds' robust spread (log_change_mad_scaled) around the change, so one outlier that sets
// today's interval does not make a scene look hopeless. At least the rounds the interval needs
// to be bounded, and at least one more round. nullopt for a summary that is not on confidence
// sequences, a change within a tenth of the limit, or one beyond ten million rounds.
// `later_spread`: the rounds from now on are spread like this instead (the fastest of two runs
// per side, measure/fastest_of_two.h); the projection then mixes the rounds so far, at their
// spread, with the rounds to come, at this one.
std::optional<std::size_t> estimated_rounds_to_decide(
    const ChangeSummary& summary, double threshold,
    std::optional<double> later_spread = std::nullopt);

// The largest spread of the rounds (scaled MAD of their log-changes) at which an unchanged scene
// is projected UNCHANGED after `rounds` rounds: its equivalence sequence at
// `equivalence_confidence` inside +-threshold (the projection of estimated_rounds_to_decide).
// nullopt while that sequence is unbounded, or for a level or threshold out of range. What a
// runner's noise must be below for the rounds a compare could afford.
std::optional<double> largest_deciding_spread(std::size_t rounds, double threshold,
                                              double equivalence_confidence);

// The interval a verdict was drawn from, and its confidence, so a report prints the one that
// decided: on confidence sequences, the equivalence sequence for UNCHANGED (it must lie within
// the limit) and the decision sequence for REGRESSED and IMPROVED (what a regression must
// clear); for INCONCLUSIVE the one that would decide it at the limit `threshold`: the
// equivalence sequence for a change inside the limit, else the decision sequence. Every output
// (report tables, gate reasons, the undecided line) names the same interval for a scene.
// Otherwise (one-look summaries) the change interval.
struct DecidingInterval {
  Interval interval;
  double confidence = 0.0;
  ChangeIntervalKind kind = ChangeIntervalKind::order_statistic;
};
DecidingInterval deciding_interval(const ChangeSummary& summary, ChangeVerdict verdict,
                                   double threshold);

// The one name every output gives an interval (reports, gate reasons, progress lines, docs):
// "99.33% CS" for an anytime-valid confidence sequence, "95% CI" for a one-look interval.
std::string interval_name(const DecidingInterval& interval);
// What the abbreviations stand for, said once where a reader meets them (policy lines, footers).
inline constexpr const char* kIntervalLegend =
    "CS = anytime-valid confidence sequence, CI = one-look confidence interval";

// The rounds before the deciding interval is bounded (below them it is only the observed range
// and no verdict but INCONCLUSIVE is drawn from it); 0 for a one-look interval or an exact change.
std::size_t rounds_to_bound(const ChangeSummary& summary, const DecidingInterval& interval);

// The change as every output prints it, with the interval `verdict` was drawn from at the limit
// `threshold` (deciding_interval):
// "+7.9% [+6.1%, +9.8%] 99.33% CS"; "+0.4%, no interval yet (needs 16 rounds)" while that
// interval is unbounded; "+0.912% exact (simulated cycles)" for a counted change.
std::string change_with_interval(const ChangeSummary& summary, ChangeVerdict verdict,
                                 double threshold);

}  // namespace raygate

#include "measure/change.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include <fmt/core.h>

#include "core/enum_words.h"
#include "core/error.h"
#include "core/format.h"
#include "measure/confidence_sequence.h"
#include "measure/descriptive.h"
#include "measure/median_interval.h"
#include "measure/probability.h"

namespace raygate {
namespace {

std::vector<RoundSample> against_baseline(std::span<const CompareRound> rounds,
                                          double CompareRound::*revision) {
  std::vector<RoundSample> samples;
  samples.reserve(rounds.size());
  for (const CompareRound& r : rounds) {
    if (r.baseline_seconds) samples.push_back({r.*revision, *r.baseline_seconds});
  }
  return samples;
}

// An interval of log changes in change-fraction units (exp is monotone).
std::optional<Interval> to_change(const std::optional<Interval>& log_interval) {
  if (!log_interval) return std::nullopt;
  return Interval{std::expm1(log_interval->lower), std::expm1(log_interval->upper)};
}

// The expected position of a median sequence's upper end among n values (Blom), as a
// probability; nullopt while the sequence is unbounded.
std::optional<double> upper_end_position(std::size_t n, double alpha_each_side) {
  const std::size_t rank = median_sequence_upper_rank(n, alpha_each_side);
  if (rank > n) return std::nullopt;
  return (static_cast<double>(rank) - 0.375) / (static_cast<double>(n) + 0.25);
}

// P(X <= x) for X normal around 0 with this spread (a step at 0 for spread 0).
double normal_cdf(double x, double spread) {
  if (!(spread > 0.0)) return x >= 0.0 ? 1.0 : 0.0;
  return 0.5 * std::erfc(-x / (spread * std::sqrt(2.0)));
}

// Where an undecided scene's intervals will be after n rounds in all, if its rounds go on as
// they went: a confidence sequence's ends are order statistics whose ranks depend on n alone
// (median_sequence_upper_rank), and the j-th of n values spread like a normal around the
// median ℓ with the rounds' robust spread σ (scaled MAD of the log-changes) lies near
// ℓ + σ Φ⁻¹((j - 0.375) / (n + 0.25)) (Blom's approximation). The spread is the MAD's and not
// the interval's own width: a few rounds in, that width is the range of the rounds, which one
// outlier from a host's hiccup sets, while the sequence's ranks move past it within a few rounds
// more. (The identity tracer's teapot after 8 rounds, all within 0.7% of each other but one at
// -20%, was estimated at 374 rounds by a square law on that width.)
class RoundsProjection {
 public:
  // Projected round by round up to here; beyond, the half-width's square law from this round.
  static constexpr std::size_t kMaxRounds = 2048;

  // The rounds so far are spread like summary.log_change_mad_scaled; the rounds still to come
  // like `later_spread` when given (the fastest of two runs per side, measure/fastest_of_two.h),
  // so the sequence after n rounds is projected from a mixture of the two.
  RoundsProjection(const ChangeSummary& summary, double threshold,
                   std::optional<double> later_spread)
      : log_change_(std::log1p(summary.change)),
        spread_(summary.log_change_mad_scaled),
        later_spread_(later_spread.value_or(summary.log_change_mad_scaled)),
        rounds_now_(summary.rounds),
        threshold_(threshold),
        towards_unchanged_(std::abs(summary.change) < threshold),
        equivalence_alpha_((1.0 - summary.equivalence_confidence) / 2.0),
        decision_alpha_((1.0 - summary.confidence) / 2.0) {}

  // Whether the verdict the scene is nearer to holds after n rounds (classify_sequential's
  // conditions on the projected intervals).
  bool decides_at(std::size_t n) const {
    if (towards_unchanged_) {
      const double half = half_width(n, equivalence_alpha_);
      return std::expm1(log_change_ + half) <= threshold_ &&
             std::expm1(log_change_ - half) >= -threshold_;
    }
    const double size = std::abs(log_change_);
    const double decision_half = half_width(n, decision_alpha_);
    // The one-look 95% interval of a median: about 1.96 x 1.2533 sigma / sqrt(n) each side.
    const double one_look_half =
        1.96 * 1.2533 * median_spread(n) / std::sqrt(static_cast<double>(n));
    return decision_half < size &&
           (one_look_half <= threshold_ || decision_half < size - std::log1p(threshold_));
  }

  // Past kMaxRounds the sequence narrows about like 1/sqrt(n): the rounds at which the
  // projected half-width at kMaxRounds would shrink to the room the verdict leaves; nullopt
  // when that is beyond any budget (ten million rounds).
  std::optional<std::size_t> beyond_max_rounds() const {
    const double alpha = towards_unchanged_ ? equivalence_alpha_ : decision_alpha_;
    const double half = half_width(kMaxRounds, alpha);
    const double room = towards_unchanged_ ? std::min(std::log1p(threshold_) - log_change_,
                                                      log_change_ - std::log1p(-threshold_))
                                           : std::abs(log_change_);
    if (!(room > 0.0)) return std::nullopt;
    const double rounds = static_cast<double>(kMaxRounds) * (half / room) * (half / room);
    if (!(rounds <= 1e7)) return std::nullopt;
    return std::max(kMaxRounds + 1, static_cast<std::size_t>(std::ceil(rounds)));
  }

 private:
  // The projected distance from the change to the sequence's ends after n rounds: where the
  // upper end's rank falls among n values, of which the first rounds_now_ are spread like
  // spread_ and the rest like later_spread_; infinite while the sequence is unbounded.
  double half_width(std::size_t n, double alpha) const {
    const std::optional<double> position = upper_end_position(n, alpha);
    if (!position) return std::numeric_limits<double>::infinity();
    const double z = normal_quantile(*position);
    if (later_spread_ == spread_ || n <= rounds_now_) return spread_ * z;
    // The mixture's quantile lies between its parts' (z > 0: an upper end), found by bisection.
    const double now_share = static_cast<double>(rounds_now_) / static_cast<double>(n);
    double low = std::min(spread_, later_spread_) * z;
    double high = std::max(spread_, later_spread_) * z;
    for (int step = 0; step < 60 && high - low > 1e-9; ++step) {
      const double middle = 0.5 * (low + high);
      const double below = now_share * normal_cdf(middle, spread_) +
                           (1.0 - now_share) * normal_cdf(middle, later_spread_);
      (below < *position ? low : high) = middle;
    }
    return high;
  }

  // The spread whose median is as precise as the mixture's after n rounds: a median's variance
  // is 1 / (4 n f(0)^2), and the mixture's density at its centre is the rounds' shares of each
  // part's, 1 / (sigma sqrt(2 pi)).
  double median_spread(std::size_t n) const {
    if (later_spread_ == spread_ || n <= rounds_now_) return spread_;
    if (!(spread_ > 0.0 && later_spread_ > 0.0)) return 0.0;
    const double now_share = static_cast<double>(rounds_now_) / static_cast<double>(n);
    return 1.0 / (now_share / spread_ + (1.0 - now_share) / later_spread_);
  }

  double log_change_;
  double spread_;
  double later_spread_;
  std::size_t rounds_now_;
  double threshold_;
  bool towards_unchanged_;
  double equivalence_alpha_;
  double decision_alpha_;
};

}  // namespace

ChangeSummary summarize_change(std::span<const CompareRound> rounds,
                               const BootstrapOptions& options,
                               const std::optional<SequenceLevels>& sequence) {
  if (rounds.empty()) throw std::invalid_argument("summarize_change: no rounds");
  const std::vector<RoundSample> base_rounds =
      against_baseline(rounds, &CompareRound::base_seconds);
  const std::vector<RoundSample> head_rounds =
      against_baseline(rounds, &CompareRound::head_seconds);
  // log_ratios validates the rounds with a baseline, log_changes every round.
  const std::vector<double> base_logs = log_ratios(base_rounds);
  const std::vector<double> head_logs = log_ratios(head_rounds);
  const std::vector<double> log_changes = compare_log_changes(rounds);

  ChangeSummary summary;
  summary.rounds = rounds.size();
  summary.log_change_median = median(log_changes);
  summary.change = std::expm1(summary.log_change_median);
  summary.confidence = options.confidence;
  // An interval still unbounded (too few rounds) is reported as the observed range, which
  // classify_change will not decide on.
  const auto [lowest, highest] = std::minmax_element(log_changes.begin(), log_changes.end());
  const Interval observed{std::expm1(*lowest), std::expm1(*highest)};
  if (sequence) {
    const SequentialIntervals s = sequential_intervals(log_changes, *sequence);
    summary.interval_kind = ChangeIntervalKind::confidence_sequence;
    summary.confidence = 1.0 - 2.0 * sequence->decision_alpha;
    summary.change_interval = s.decision.value_or(observed);
    summary.equivalence_confidence = 1.0 - 2.0 * sequence->equivalence_alpha;
    summary.equivalence_interval = s.equivalence.value_or(observed);
    summary.one_look_confidence = sequence->one_look_confidence;
    summary.one_look_interval = s.one_look.value_or(observed);
  } else {
    summary.change_interval =
        to_change(median_interval(log_changes, options.confidence)).value_or(observed);
  }
  summary.log_change_mad_scaled = mad_scaled(log_changes);
  if (!base_rounds.empty()) {
    summary.base = summarize_ratio(base_rounds, options.confidence);
    summary.head = ratio_through_change(
        summary.base, summarize_ratio(head_rounds, options.confidence), summary.change);
    // Ranks are unchanged by exp, so testing the log-ratios is testing the ratios.
    summary.mann_whitney = mann_whitney_u(head_logs, base_logs);
  }
  return summary;
}

RatioSummary ratio_through_change(const RatioSummary& base, const RatioSummary& head_own,
                                  double change) {
  RatioSummary head = head_own;
  const double factor = 1.0 + change;
  head.ratio = base.ratio * factor;
  head.ratio_interval = {base.ratio_interval.lower * factor, base.ratio_interval.upper * factor};
  head.relative_half_width = base.relative_half_width;
  head.log_ratio_median = base.log_ratio_median + std::log1p(change);
  return head;
}

std::vector<double> compare_log_changes(std::span<const CompareRound> rounds) {
  std::vector<double> log_changes;
  log_changes.reserve(rounds.size());
  for (std::size_t i = 0; i < rounds.size(); ++i) {
    const CompareRound& r = rounds[i];
    for (const double seconds : {r.base_seconds, r.head_seconds}) {
      if (!(seconds > 0.0 && std::isfinite(seconds))) {
        throw InfraError(
            fmt::format("round {}: a time of {} s cannot be compared; a change needs "
                        "positive times",
                        i + 1, seconds));
      }
    }
    log_changes.push_back(std::log(r.head_seconds / r.base_seconds));
  }
  return log_changes;
}

// The verdicts' words, each spelt once: documents, store rows and the console print them.
constexpr EnumWords<ChangeVerdict, 4> kVerdictWords{
    {{ChangeVerdict::unchanged, "UNCHANGED"},
     {ChangeVerdict::improved, "IMPROVED"},
     {ChangeVerdict::regressed, "REGRESSED"},
     {ChangeVerdict::inconclusive, "INCONCLUSIVE"}}};
constexpr EnumWords<ChangeIntervalKind, 2> kIntervalKindWords{
    {{ChangeIntervalKind::order_statistic, "order-statistic"},
     {ChangeIntervalKind::confidence_sequence, "confidence-sequence"}}};

std::string_view to_string(ChangeVerdict verdict) {
  return word_of(kVerdictWords, verdict, "UNKNOWN");
}

std::optional<ChangeVerdict> change_verdict_named(std::string_view word) {
  return value_of(kVerdictWords, word);
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

std::string_view to_string(ChangeIntervalKind kind) {
  return word_of(kIntervalKindWords, kind, "order-statistic");
}

std::optional<ChangeIntervalKind> change_interval_kind(std::string_view text) {
  return value_of(kIntervalKindWords, text);
}

SequentialIntervals sequential_intervals(std::span<const double> log_changes,
                                         const SequenceLevels& levels) {
  SequentialIntervals s;
  s.change = std::expm1(median(log_changes));
  s.decision = to_change(median_sequence_interval(log_changes, levels.decision_alpha));
  s.equivalence = to_change(median_sequence_interval(log_changes, levels.equivalence_alpha));
  s.one_look = to_change(median_interval(log_changes, levels.one_look_confidence));
  return s;
}

ChangeVerdict classify_sequential(const SequentialIntervals& s, double threshold) {
  if (!(threshold >= 0.0)) throw std::invalid_argument("classify_change: negative threshold");
  // The decision interval carries the error guarantee (REGRESSED only when it excludes 0); the
  // one-look interval only says whether the median is known well enough to compare it with
  // the limit, the job the decision interval did in the one-look rule.
  if (s.decision && s.one_look) {
    const Interval& d = *s.decision;
    const bool precise = s.one_look->upper - s.one_look->lower <= 2.0 * threshold;
    if (d.lower > 0.0 && s.change > threshold && (precise || d.lower > threshold)) {
      return ChangeVerdict::regressed;
    }
    if (d.upper < 0.0 && s.change < -threshold && (precise || d.upper < -threshold)) {
      return ChangeVerdict::improved;
    }
  }
  if (s.equivalence && s.equivalence->lower >= -threshold && s.equivalence->upper <= threshold) {
    return ChangeVerdict::unchanged;
  }
  return ChangeVerdict::inconclusive;
}

ChangeVerdict classify_change(const ChangeSummary& summary, double threshold) {
  // Counted and repeated (sim mode): the change is exact, its interval a point, however few
  // rounds; it is judged against the limit directly.
  if (summary.exact) return classify_change(summary.change, summary.change_interval, threshold);
  if (summary.interval_kind == ChangeIntervalKind::confidence_sequence) {
    const auto bounded = [&](const Interval& interval, std::size_t needed) {
      return summary.rounds >= needed ? std::optional<Interval>(interval) : std::nullopt;
    };
    SequentialIntervals s;
    s.change = summary.change;
    s.decision = bounded(summary.change_interval,
                         min_values_for_median_sequence((1.0 - summary.confidence) / 2.0));
    s.equivalence =
        bounded(summary.equivalence_interval,
                min_values_for_median_sequence((1.0 - summary.equivalence_confidence) / 2.0));
    s.one_look = bounded(summary.one_look_interval,
                         min_values_for_median_interval(summary.one_look_confidence));
    return classify_sequential(s, threshold);
  }
  if (summary.rounds < min_values_for_median_interval(summary.confidence)) {
    return ChangeVerdict::inconclusive;
  }
  return classify_change(summary.change, summary.change_interval, threshold);
}

std::optional<std::size_t> estimated_rounds_to_decide(const ChangeSummary& summary,
                                                      double threshold,
                                                      std::optional<double> later_spread) {
  if (summary.interval_kind != ChangeIntervalKind::confidence_sequence || summary.rounds == 0) {
    return std::nullopt;
  }
  // Below the rounds the interval that decides needs to be bounded at all, those rounds are the
  // estimate: a point estimate and a spread from a handful of rounds say too little to call a
  // scene hopeless or cheap.
  const std::size_t to_bound =
      rounds_to_bound(summary, deciding_interval(summary, ChangeVerdict::inconclusive, threshold));
  if (summary.rounds < to_bound) return to_bound;
  // Within a tenth of the limit the point estimate itself may fall on either side of it
  // whatever the rounds: no estimate.
  if (std::abs(std::abs(summary.change) - threshold) < 0.1 * threshold) return std::nullopt;
  const RoundsProjection projection(summary, threshold, later_spread);
  const std::size_t first = summary.rounds + 1;  // undecided now, so at least one more round
  // Round by round while the sequence's rank steps make the projection jump back and forth
  // (its range at 8 rounds is narrower than at 10); beyond, it narrows steadily, so the first
  // deciding round is found by doubling and halving.
  // A document may claim any number of rounds: past the projected range the square law
  // answers, without scanning ranks a count of rounds that large would need.
  if (first > RoundsProjection::kMaxRounds) {
    const std::optional<std::size_t> beyond = projection.beyond_max_rounds();
    return beyond ? std::optional<std::size_t>(std::max(*beyond, first)) : std::nullopt;
  }
  constexpr std::size_t kSteadyFrom = 64;
  for (std::size_t n = first; n <= kSteadyFrom; ++n) {
    if (projection.decides_at(n)) return n;
  }
  std::size_t low = std::max(first, kSteadyFrom);  // does not decide
  std::size_t high = low;
  while (!projection.decides_at(high)) {
    if (high >= RoundsProjection::kMaxRounds) {
      const std::optional<std::size_t> beyond = projection.beyond_max_rounds();
      return beyond ? std::optional<std::size_t>(std::max(*beyond, first)) : std::nullopt;
    }
    low = high;
    high = std::min(2 * high, RoundsProjection::kMaxRounds);
  }
  while (high - low > 1) {
    const std::size_t middle = low + (high - low) / 2;
    (projection.decides_at(middle) ? high : low) = middle;
  }
  return high;
}

std::optional<double> largest_deciding_spread(std::size_t rounds, double threshold,
                                              double equivalence_confidence) {
  const double alpha = (1.0 - equivalence_confidence) / 2.0;
  if (!(alpha > 0.0 && alpha < 0.5) || !(threshold > 0.0)) return std::nullopt;
  // Past the projected range the sequence narrows like 1/sqrt(rounds) (and a stored document
  // may claim any number of rounds: no rank scan that long).
  const std::size_t projected = std::min(rounds, RoundsProjection::kMaxRounds);
  const std::optional<double> position = upper_end_position(projected, alpha);
  if (!position) return std::nullopt;
  const double z = normal_quantile(*position) *
                   std::sqrt(static_cast<double>(projected) / static_cast<double>(rounds));
  if (!std::isfinite(z) || !(z > 0.0)) return std::nullopt;
  return std::log1p(threshold) / z;
}

DecidingInterval deciding_interval(const ChangeSummary& summary, ChangeVerdict verdict,
                                   double threshold) {
  const bool towards_unchanged =
      verdict == ChangeVerdict::unchanged ||
      (verdict == ChangeVerdict::inconclusive && std::abs(summary.change) < threshold);
  if (summary.interval_kind == ChangeIntervalKind::confidence_sequence && !summary.exact &&
      towards_unchanged) {
    return {summary.equivalence_interval, summary.equivalence_confidence, summary.interval_kind};
  }
  return {summary.change_interval, summary.confidence, summary.interval_kind};
}

std::string interval_name(const DecidingInterval& interval) {
  const bool sequence = interval.kind == ChangeIntervalKind::confidence_sequence;
  return fmt::format("{:.4g}% {}", 100.0 * interval.confidence, sequence ? "CS" : "CI");
}

std::size_t rounds_to_bound(const ChangeSummary& summary, const DecidingInterval& interval) {
  if (summary.exact || interval.kind != ChangeIntervalKind::confidence_sequence) return 0;
  return min_values_for_median_sequence((1.0 - interval.confidence) / 2.0);
}

namespace {

// Decimals for an interval's bounds: one, or more while a bound would print as a line it is
// judged against, the limit or zero, without being on it ("[-0.7%, +3.0%]" beside UNCHANGED
// within ±3% read as a contradiction; the bound was +2.984%).
int bound_decimals(const Interval& interval, double threshold) {
  const auto prints_as = [](double bound, double line, int decimals) {
    const double scale = 100.0 * std::pow(10.0, decimals);
    return std::abs(bound) != line &&
           std::round(std::abs(bound) * scale) == std::round(line * scale);
  };
  const auto misleading = [&](int decimals) {
    for (const double bound : {interval.lower, interval.upper}) {
      if (prints_as(bound, std::abs(threshold), decimals) || prints_as(bound, 0.0, decimals)) {
        return true;
      }
    }
    return false;
  };
  int decimals = 1;
  while (decimals < 3 && misleading(decimals)) ++decimals;
  return decimals;
}

}  // namespace

std::string change_with_interval(const ChangeSummary& summary, ChangeVerdict verdict,
                                 double threshold) {
  // Counted in simulated cycles, every count repeated: the change is a fact, not an estimate.
  if (summary.exact) return signed_percent(summary.change, 3) + " exact (simulated cycles)";
  const DecidingInterval decided = deciding_interval(summary, verdict, threshold);
  if (const std::size_t needed = rounds_to_bound(summary, decided); summary.rounds < needed) {
    return fmt::format("{}, no interval yet (needs {} rounds)", signed_percent(summary.change),
                       needed);
  }
  const int decimals = bound_decimals(decided.interval, threshold);
  return fmt::format("{} [{}, {}] {}", signed_percent(summary.change),
                     signed_percent(decided.interval.lower, decimals),
                     signed_percent(decided.interval.upper, decimals), interval_name(decided));
}

}  // namespace raygate

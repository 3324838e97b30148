// Change between two revisions: the paired change and its CI, Mann-Whitney U against values
// worked by hand, and the verdict table of docs/statistics.md.
#include "measure/change.h"
#include "measure/confidence_sequence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "core/error.h"
#include "measure/descriptive.h"
#include "measure/mann_whitney.h"
#include "synthetic.h"
#include "vm_noise.h"

namespace raygate {
namespace {

using testing::compare_rounds;

TEST(MeasureMannWhitney, SeparatedSamples) {
  // U_a = 0; mean 4.5; var = 3*3/12 * 7 = 5.25; z = (4.5 - 0.5) / sqrt(5.25) = 1.74574.
  const MannWhitneyResult r =
      mann_whitney_u(std::vector<double>{1, 2, 3}, std::vector<double>{4, 5, 6});
  EXPECT_DOUBLE_EQ(r.u, 0.0);
  EXPECT_NEAR(r.z, -1.7457431218879391, 1e-12);
  EXPECT_NEAR(r.p_value, 0.0808555983700523, 1e-12);  // R: wilcox.test(exact = FALSE) 0.08086
}

TEST(MeasureMannWhitney, TiesUseMidranksAndCorrectedVariance) {
  // Pooled ranks: 1 | 2 2 2 -> 3 | 3 3 -> 5.5 | 4 -> 7 | 5 -> 8. R_a = 1 + 3 + 3 + 5.5 = 12.5,
  // U_a = 12.5 - 10 = 2.5. Ties: (27 - 3) + (8 - 2) = 30; var = 16/12 (9 - 30/56) = 11.2857;
  // z = (5.5 - 0.5) / sqrt(var) = 1.48835; p = erfc(z / sqrt 2) = 0.13666.
  const MannWhitneyResult r =
      mann_whitney_u(std::vector<double>{1, 2, 2, 3}, std::vector<double>{2, 3, 4, 5});
  EXPECT_DOUBLE_EQ(r.u, 2.5);
  EXPECT_NEAR(r.z, -1.4883513944689681, 1e-12);
  EXPECT_NEAR(r.p_value, 0.13665824773814753, 1e-12);
}

TEST(MeasureMannWhitney, SymmetricAndDegenerate) {
  const MannWhitneyResult swapped =
      mann_whitney_u(std::vector<double>{4, 5, 6}, std::vector<double>{1, 2, 3});
  EXPECT_DOUBLE_EQ(swapped.u, 9.0);
  EXPECT_NEAR(swapped.p_value, 0.0808555983700523, 1e-12);
  const MannWhitneyResult tied =
      mann_whitney_u(std::vector<double>{1, 1}, std::vector<double>{1, 1, 1});
  EXPECT_DOUBLE_EQ(tied.u, 3.0);
  EXPECT_DOUBLE_EQ(tied.p_value, 1.0);
  const MannWhitneyResult centred =
      mann_whitney_u(std::vector<double>{1, 4}, std::vector<double>{2, 3});
  EXPECT_DOUBLE_EQ(centred.u, 2.0);  // exactly the mean: p = 1, z = 0
  EXPECT_DOUBLE_EQ(centred.p_value, 1.0);
  EXPECT_THROW(mann_whitney_u(std::vector<double>{}, std::vector<double>{1}),
               std::invalid_argument);
}

TEST(MeasureChange, BaselineCancelsWithinARound) {
  // Baseline times are wild, head is exactly 10% slower than base in every round.
  const std::vector<CompareRound> rounds{{1.0, 2.0, 2.2}, {3.0, 2.5, 2.75}, {0.5, 1.0, 1.1}};
  const ChangeSummary s = summarize_change(rounds);
  EXPECT_NEAR(s.change, 0.10, 1e-12);
  EXPECT_NEAR(s.change_interval.lower, 0.10, 1e-12);
  EXPECT_NEAR(s.change_interval.upper, 0.10, 1e-12);
  EXPECT_NEAR(s.base.ratio, 2.0, 1e-12);  // median of 2, 0.833, 2
  EXPECT_EQ(s.rounds, 3u);
}

TEST(MeasureChange, RoundsWithoutABaselineCountForTheChangeOnly) {
  // The baseline joined the first two rounds (ScheduleOptions::normalizer_rounds).
  const std::vector<CompareRound> rounds{
      {1.0, 2.0, 2.2}, {4.0, 2.0, 2.2}, {std::nullopt, 2.0, 2.2}, {std::nullopt, 1.0, 1.1}};
  const ChangeSummary s = summarize_change(rounds);
  EXPECT_EQ(s.rounds, 4u);
  EXPECT_NEAR(s.change, 0.10, 1e-12);
  EXPECT_EQ(s.base.rounds, 2u);
  EXPECT_NEAR(s.base.ratio, std::sqrt(2.0 * 0.5), 1e-12);  // geometric mean of 2 and 0.5
  // No baseline at all: the change alone, and ratios of no rounds.
  const ChangeSummary bare = summarize_change(std::vector<CompareRound>{{std::nullopt, 1.0, 1.2}});
  EXPECT_NEAR(bare.change, 0.2, 1e-12);
  EXPECT_EQ(bare.head.rounds, 0u);
  EXPECT_THROW(summarize_change(std::vector<CompareRound>{{std::nullopt, 0.0, 1.0}}), InfraError);
}

TEST(MeasureChange, PairingCancelsRoundDrift) {
  // +-20% drift across rounds, 1% noise per run: the paired CI is far tighter than the drift.
  Xoshiro256 rng(3);
  const ChangeSummary s = summarize_change(compare_rounds(rng, 30, 1.05, 0.01));
  EXPECT_TRUE(s.change_interval.contains(s.change));
  EXPECT_GT(s.change_interval.lower, 0.03);
  EXPECT_LT(s.change_interval.upper, 0.07);
  EXPECT_LT(s.mann_whitney.p_value, 0.05);
  EXPECT_GT(s.mann_whitney.u, 30.0 * 30.0 / 2.0);  // head's ratios tend to be larger
}

ChangeVerdict verdict_for(std::uint64_t seed, int rounds, double true_factor, double log_sigma) {
  Xoshiro256 rng(seed);
  return classify_change(summarize_change(compare_rounds(rng, rounds, true_factor, log_sigma)));
}

TEST(MeasureVerdict, ClearRegression) {
  EXPECT_EQ(verdict_for(1, 15, 1.10, 0.01), ChangeVerdict::regressed);
}

TEST(MeasureVerdict, ClearImprovement) {
  EXPECT_EQ(verdict_for(2, 15, 0.90, 0.01), ChangeVerdict::improved);
}

TEST(MeasureVerdict, AaIsUnchanged) {
  EXPECT_EQ(verdict_for(3, 20, 1.00, 0.005), ChangeVerdict::unchanged);
}

TEST(MeasureVerdict, NoisyIsInconclusive) {
  EXPECT_EQ(verdict_for(4, 8, 1.03, 0.10), ChangeVerdict::inconclusive);
}

TEST(MeasureVerdict, SmallSignificantChangeUnderThresholdIsUnchanged) {
  Xoshiro256 rng(5);
  const ChangeSummary s = summarize_change(compare_rounds(rng, 40, 1.01, 0.003));
  EXPECT_GT(s.change_interval.lower, 0.0);                  // significant ...
  EXPECT_EQ(classify_change(s), ChangeVerdict::unchanged);  // ... but practically nothing
}

TEST(MeasureVerdict, TableOnNumbers) {
  const double t = kDefaultChangeThreshold;
  EXPECT_EQ(classify_change(0.05, {0.04, 0.06}, t), ChangeVerdict::regressed);
  EXPECT_EQ(classify_change(0.035, {0.001, 0.06}, t), ChangeVerdict::regressed);
  // Significant and over the limit by the estimate, but the estimate is only known to +-12%:
  // a +1% commit measured so under load. Not precise enough to call.
  EXPECT_EQ(classify_change(0.035, {0.005, 0.243}, t), ChangeVerdict::inconclusive);
  // Imprecise, but wholly beyond the limit: precise enough.
  EXPECT_EQ(classify_change(0.40, {0.20, 0.80}, t), ChangeVerdict::regressed);
  EXPECT_EQ(classify_change(-0.40, {-0.60, -0.20}, t), ChangeVerdict::improved);
  EXPECT_EQ(classify_change(-0.035, {-0.243, -0.005}, t), ChangeVerdict::inconclusive);
  EXPECT_EQ(classify_change(0.035, {-0.005, 0.07}, t), ChangeVerdict::inconclusive);
  EXPECT_EQ(classify_change(0.02, {0.005, 0.035}, t), ChangeVerdict::inconclusive);
  EXPECT_EQ(classify_change(0.01, {0.008, 0.012}, t), ChangeVerdict::unchanged);
  EXPECT_EQ(classify_change(0.0, {-0.03, 0.03}, t), ChangeVerdict::unchanged);
  EXPECT_EQ(classify_change(-0.05, {-0.06, -0.04}, t), ChangeVerdict::improved);
  EXPECT_EQ(classify_change(-0.02, {-0.035, -0.005}, t), ChangeVerdict::inconclusive);
  EXPECT_EQ(classify_change(0.0, {-0.2, 0.2}, t), ChangeVerdict::inconclusive);
  EXPECT_EQ(classify_change(0.05, {0.04, 0.06}, 0.10), ChangeVerdict::unchanged);
}

TEST(MeasureVerdict, Names) {
  EXPECT_EQ(to_string(ChangeVerdict::regressed), "REGRESSED");
  EXPECT_EQ(to_string(ChangeVerdict::improved), "IMPROVED");
  EXPECT_EQ(to_string(ChangeVerdict::unchanged), "UNCHANGED");
  EXPECT_EQ(to_string(ChangeVerdict::inconclusive), "INCONCLUSIVE");
}

// A summary on confidence sequences with the intervals given, in change units, and the rounds'
// spread (scaled MAD of their log-changes).
ChangeSummary sequence_summary(double change, Interval decision, Interval equivalence,
                               std::size_t rounds, double spread = 0.0) {
  ChangeSummary s;
  s.rounds = rounds;
  s.change = change;
  s.log_change_mad_scaled = spread;
  s.interval_kind = ChangeIntervalKind::confidence_sequence;
  s.change_interval = decision;
  s.confidence = 0.9985;
  s.equivalence_interval = equivalence;
  s.equivalence_confidence = 0.90;
  return s;
}

TEST(MeasureDecidingInterval, UnchangedPrintsTheEquivalenceSequenceAndTheRestTheDecisionOne) {
  const ChangeSummary s = sequence_summary(0.004, {-0.20, 0.28}, {-0.012, 0.020}, 15);
  const DecidingInterval unchanged = deciding_interval(s, ChangeVerdict::unchanged, 0.03);
  EXPECT_DOUBLE_EQ(unchanged.interval.upper, 0.020);
  EXPECT_DOUBLE_EQ(unchanged.confidence, 0.90);
  for (const ChangeVerdict v : {ChangeVerdict::regressed, ChangeVerdict::improved}) {
    EXPECT_DOUBLE_EQ(deciding_interval(s, v, 0.03).interval.upper, 0.28);
    EXPECT_DOUBLE_EQ(deciding_interval(s, v, 0.03).confidence, 0.9985);
  }
  // INCONCLUSIVE names the interval that would decide it: inside the limit the equivalence
  // sequence UNCHANGED needs, beyond it the decision sequence a regression must clear.
  EXPECT_DOUBLE_EQ(deciding_interval(s, ChangeVerdict::inconclusive, 0.03).confidence, 0.90);
  EXPECT_DOUBLE_EQ(deciding_interval(s, ChangeVerdict::inconclusive, 0.003).confidence, 0.9985);
  EXPECT_EQ(change_verdict_named("UNCHANGED"), ChangeVerdict::unchanged);
  EXPECT_FALSE(change_verdict_named("unchanged").has_value());
}

TEST(MeasureChangeWords, EveryVerdictAndIntervalKindReadsBackFromItsWord) {
  for (const ChangeVerdict v : {ChangeVerdict::unchanged, ChangeVerdict::improved,
                                ChangeVerdict::regressed, ChangeVerdict::inconclusive}) {
    EXPECT_EQ(change_verdict_named(to_string(v)), v);
  }
  EXPECT_EQ(to_string(ChangeVerdict::inconclusive), "INCONCLUSIVE");
  for (const ChangeIntervalKind kind :
       {ChangeIntervalKind::order_statistic, ChangeIntervalKind::confidence_sequence}) {
    EXPECT_EQ(change_interval_kind(to_string(kind)), kind);
  }
  EXPECT_EQ(to_string(ChangeIntervalKind::confidence_sequence), "confidence-sequence");
  EXPECT_FALSE(change_interval_kind("order_statistic").has_value());
}

TEST(MeasureRoundsToDecide, ProjectFromTheRoundsSpreadNotFromOneOutlier) {
  // The identity tracer's teapot after 8 rounds: every round within 0.7% of the others but one
  // at -20%. The equivalence sequence is the rounds' range, so its width says hundreds of
  // rounds; the rounds' spread (0.4%) says the sequence's ranks need only pass that one round.
  const std::optional<std::size_t> teapot = estimated_rounds_to_decide(
      sequence_summary(-0.001, {-0.2, 0.2}, {-0.2, 0.007}, 8, 0.004), 0.03);
  ASSERT_TRUE(teapot);
  EXPECT_GE(*teapot, 9u);
  EXPECT_LE(*teapot, 15u);
  // Twice the spread, about four times the rounds (the ranks' log factor adds a little).
  const auto at_spread = [](double spread) {
    return *estimated_rounds_to_decide(sequence_summary(0.0, {-1, 1}, {-1, 1}, 10, spread), 0.03);
  };
  EXPECT_GT(at_spread(0.06), 3 * at_spread(0.03));
  EXPECT_LT(at_spread(0.06), 5 * at_spread(0.03));
  // Closer to the limit, more rounds; a scene already as good as decided, one more.
  EXPECT_GT(*estimated_rounds_to_decide(sequence_summary(0.02, {-1, 1}, {-1, 1}, 10, 0.03), 0.03),
            at_spread(0.03));
  EXPECT_EQ(
      estimated_rounds_to_decide(sequence_summary(0.0, {-0.1, 0.1}, {-0.029, 0.029}, 27), 0.03),
      28u);
}

TEST(MeasureRoundsToDecide, TowardsAVerdictOfChangeTheDecisionSequenceMustClearZero) {
  // +6% with rounds spread 8%: the 99.85% sequence must come 6 points in from the change, and
  // the bigger the change, the sooner.
  const std::size_t six =
      *estimated_rounds_to_decide(sequence_summary(0.06, {-0.03, 0.2}, {0.0, 0.1}, 40, 0.08), 0.03);
  const std::size_t twelve =
      *estimated_rounds_to_decide(sequence_summary(0.12, {-0.03, 0.3}, {0.0, 0.2}, 40, 0.08), 0.03);
  EXPECT_GT(six, 40u);
  EXPECT_LT(twelve, six);
  // Far beyond the projected rounds the half-width's square law carries on, up to ten million.
  const std::optional<std::size_t> far =
      estimated_rounds_to_decide(sequence_summary(0.04, {-0.1, 0.2}, {0.0, 0.1}, 40, 0.5), 0.03);
  ASSERT_TRUE(far);
  EXPECT_GT(*far, 2048u);
  EXPECT_FALSE(
      estimated_rounds_to_decide(sequence_summary(0.04, {-0.1, 0.2}, {0.0, 0.1}, 40, 50.0), 0.03));
}

TEST(MeasureRoundsToDecide, ARoundCountFromAHostileDocumentIsAnsweredAtOnce) {
  // A stored document may claim a trillion rounds; the ranks of such a sequence are not scanned
  // (that took longer than any CI job), the square law answers.
  const std::size_t trillion = 1'000'000'000'000;
  const std::optional<std::size_t> more =
      estimated_rounds_to_decide(sequence_summary(0.0, {-1, 1}, {-1, 1}, trillion, 0.02), 0.03);
  ASSERT_TRUE(more);
  EXPECT_GT(*more, trillion);
  const std::optional<double> spread = largest_deciding_spread(trillion, 0.03, 0.90);
  ASSERT_TRUE(spread);
  EXPECT_GT(*spread, *largest_deciding_spread(2048, 0.03, 0.90));
}

TEST(MeasureRoundsToDecide, WaitForTheBoundAndSayNothingOnTheLimitOrForOneLook) {
  // Too few rounds for the equivalence sequence to be bounded: its interval is the observed
  // range, which may fit already (identical times), but the verdict waits for the bound.
  EXPECT_EQ(estimated_rounds_to_decide(sequence_summary(0.0, {0.0, 0.0}, {0.0, 0.0}, 4), 0.03),
            min_values_for_median_sequence(0.05));
  EXPECT_GT(min_values_for_median_sequence(0.05), 5u);
  // A change on the limit has no room: no number of rounds decides it.
  EXPECT_FALSE(
      estimated_rounds_to_decide(sequence_summary(0.03, {-0.1, 0.2}, {0.0, 0.06}, 40, 0.01), 0.03));
  // One-look summaries (older documents) are not estimated.
  ChangeSummary one_look = sequence_summary(0.01, {-0.1, 0.1}, {-0.05, 0.05}, 20, 0.01);
  one_look.interval_kind = ChangeIntervalKind::order_statistic;
  EXPECT_FALSE(estimated_rounds_to_decide(one_look, 0.03));
}

TEST(MeasureRoundsToDecide, TheLargestSpreadThatDecidesAgreesWithTheProjection) {
  // At 10 rounds the 90% sequence is the range: the 10th of 10 normals lies near 1.55 sigma
  // (Blom), so +3% is reached at sigma ln(1.03) / 1.55 = 1.9%.
  EXPECT_NEAR(*largest_deciding_spread(10, 0.03, 0.90), std::log(1.03) / 1.5459, 2e-4);
  EXPECT_GT(*largest_deciding_spread(40, 0.03, 0.90), *largest_deciding_spread(10, 0.03, 0.90));
  EXPECT_FALSE(largest_deciding_spread(5, 0.03, 0.90)) << "unbounded below 7 rounds";
  EXPECT_FALSE(largest_deciding_spread(10, 0.03, 1.0));
  for (const std::size_t rounds : {10u, 20u, 40u, 80u}) {
    const double spread = *largest_deciding_spread(rounds, 0.03, 0.90);
    const auto at = [&](double s) {
      return *estimated_rounds_to_decide(sequence_summary(0.0, {-1, 1}, {-1, 1}, 7, s), 0.03);
    };
    // Up to the steps of the sequence's ranks (its range at 8 rounds is narrower than at 10).
    EXPECT_LE(at(0.99 * spread), rounds) << rounds;
    EXPECT_GT(at(1.1 * spread), 0.9 * static_cast<double>(rounds)) << rounds;
  }
}

// The estimate is only worth its use (the second pass gives a scene what it is estimated to
// need, and INCONCLUSIVE lines print it) if simulated scenes do decide about then. On the VM's
// noise model (spikes and bursts included), estimated after 10 rounds, against the round at
// which the same stream of rounds did decide.
TEST(MeasureRoundsToDecide, AgreeWithWhenSimulatedScenesDecide) {
  const SequenceLevels levels{0.01 / 13, 0.05, 0.95};
  for (const auto& [factor, log_sigma] :
       {std::pair{1.0, 0.01}, std::pair{1.0, 0.02}, std::pair{1.08, 0.02}, std::pair{1.06, 0.01}}) {
    std::vector<double> estimated;
    std::vector<double> decided;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
      testing::VmRounds stream(seed, {log_sigma, 0.05, 0.02});
      std::vector<CompareRound> rounds;
      for (int i = 0; i < 10; ++i) rounds.push_back(stream.next(factor));
      const ChangeSummary early = summarize_change(rounds, {}, levels);
      if (classify_change(early, 0.03) != ChangeVerdict::inconclusive) continue;
      const std::optional<std::size_t> estimate = estimated_rounds_to_decide(early, 0.03);
      if (!estimate) continue;
      std::vector<double> log_changes = compare_log_changes(rounds);
      while (log_changes.size() < 600) {
        const SequentialIntervals now = sequential_intervals(log_changes, levels);
        if (classify_sequential(now, 0.03) != ChangeVerdict::inconclusive) break;
        const CompareRound next = stream.next(factor);
        log_changes.push_back(std::log(next.head_seconds / next.base_seconds));
      }
      estimated.push_back(static_cast<double>(*estimate));
      decided.push_back(static_cast<double>(log_changes.size()));
    }
    ASSERT_GE(estimated.size(), 50u) << factor << " " << log_sigma;
    // The typical scene is estimated about right, and most within a factor of two. (A square
    // law on the interval's width, the estimate before, put the median A/A scene here at about
    // 700 rounds: ten rounds in, the 90% sequence is still the rounds' whole range.)
    const double typical_ratio = median(decided) / median(estimated);
    std::size_t within_two = 0;
    for (std::size_t i = 0; i < decided.size(); ++i) {
      within_two += estimated[i] <= 2 * decided[i] && decided[i] <= 2 * estimated[i];
    }
    EXPECT_GE(2 * within_two, decided.size()) << factor << " " << log_sigma;
    EXPECT_GT(typical_ratio, 0.6) << factor << " " << log_sigma;
    EXPECT_LT(typical_ratio, 1.6) << factor << " " << log_sigma;
  }
}

}  // namespace
}  // namespace raygate

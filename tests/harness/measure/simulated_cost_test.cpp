// The sim mode's cost model and its exact verdicts: the documented weights, the counters' JSON,
// and that rounds whose counts all repeat give an exact change (0 for A/A, a decided verdict
// after two rounds), while rounds that differ give none (the caller falls back to statistics).
#include "measure/simulated_cost.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace raygate {
namespace {

SimulatedCounters counters(std::uint64_t ir, std::uint64_t l1, std::uint64_t ll) {
  SimulatedCounters c;
  c.ir = ir;
  c.i1mr = l1;  // one of each kind of miss, so every weighted term is exercised
  c.d1mr = l1;
  c.d1mw = l1;
  c.ilmr = ll;
  c.dlmr = ll;
  c.dlmw = ll;
  c.processes = 1;
  return c;
}

TEST(SimulatedCost, EstimatedCyclesWeighsMissesTenAndAHundred) {
  EXPECT_DOUBLE_EQ(estimated_cycles(counters(1000, 0, 0)), 1000.0);
  EXPECT_DOUBLE_EQ(estimated_cycles(counters(1000, 2, 0)), 1000.0 + 10 * 6);
  EXPECT_DOUBLE_EQ(estimated_cycles(counters(1000, 2, 1)), 1000.0 + 10 * 6 + 100 * 3);
  SimulatedCounters reads_only;
  reads_only.dr = 500;  // data accesses that hit cost nothing beyond their instruction
  EXPECT_DOUBLE_EQ(estimated_cycles(reads_only), 0.0);
}

TEST(SimulatedCost, CountersSumAndRoundTripThroughJson) {
  SimulatedCounters total = counters(10, 1, 1);
  total += counters(5, 2, 0);
  EXPECT_EQ(total.ir, 15u);
  EXPECT_EQ(total.d1mw, 3u);
  EXPECT_EQ(total.processes, 2);
  const nlohmann::json json = total;
  EXPECT_EQ(json.at("Ir").get<std::uint64_t>(), 15u);
  EXPECT_DOUBLE_EQ(json.at("estimated_cycles").get<double>(), estimated_cycles(total));
  EXPECT_EQ(json.get<SimulatedCounters>(), total);
}

std::vector<CompareRound> rounds(std::vector<double> base, std::vector<double> head) {
  std::vector<CompareRound> out;
  for (std::size_t i = 0; i < base.size(); ++i) out.push_back({1000.0, base[i], head[i]});
  return out;
}

TEST(SimulatedCost, IdenticalCountsGiveAnExactZeroForAA) {
  const auto exact = exact_change(rounds({1234.0, 1234.0}, {1234.0, 1234.0}));
  ASSERT_TRUE(exact);
  EXPECT_TRUE(exact->exact);
  EXPECT_EQ(exact->change, 0.0);
  EXPECT_EQ(exact->change_interval.lower, 0.0);
  EXPECT_EQ(exact->change_interval.upper, 0.0);
  EXPECT_EQ(classify_change(*exact, 0.01), ChangeVerdict::unchanged);
}

TEST(SimulatedCost, ExactChangeDecidesAfterTwoRounds) {
  const auto exact = exact_change(rounds({1000.0, 1000.0}, {1010.0, 1010.0}));
  ASSERT_TRUE(exact);
  EXPECT_NEAR(exact->change, 0.01, 1e-15);  // 1010 / 1000 - 1 in floating point
  EXPECT_EQ(classify_change(*exact, 0.005), ChangeVerdict::regressed);
  EXPECT_EQ(classify_change(*exact, 0.02), ChangeVerdict::unchanged);
  // The same numbers, not marked exact, are too few rounds for any verdict.
  ChangeSummary sampled = *exact;
  sampled.exact = false;
  EXPECT_EQ(classify_change(sampled, 0.005), ChangeVerdict::inconclusive);
}

TEST(SimulatedCost, CountsThatDifferOrOneRoundGiveNoExactChange) {
  EXPECT_FALSE(exact_change(rounds({1000.0}, {1010.0})));
  EXPECT_FALSE(exact_change(rounds({1000.0, 1003.0}, {1010.0, 1010.0})));  // 0.3% apart
  EXPECT_FALSE(exact_change(rounds({1000.0, 1000.0}, {1010.0, 1013.0})));
  std::vector<CompareRound> baseline_moved = rounds({1000.0, 1000.0}, {1010.0, 1010.0});
  baseline_moved[1].baseline_seconds = 1003.0;
  EXPECT_FALSE(exact_change(baseline_moved));
}

// A program with a polling thread (Debian's POV-Ray) repeats its counts to a few hundredths of a
// percent: counted after two rounds, the change bounded by the runs' extremes widened by the
// tolerance (0.25%).
TEST(SimulatedCost, CountsWithinTheToleranceAreBoundedByTheirExtremes) {
  const auto slower = exact_change(rounds({1000.0, 1000.5}, {1100.0, 1100.2}));
  ASSERT_TRUE(slower);
  EXPECT_TRUE(slower->exact);
  const double t = 0.0025;
  EXPECT_NEAR(slower->change_interval.lower, 1100.0 * (1 - t) / (1000.5 * (1 + t)) - 1, 1e-12);
  EXPECT_NEAR(slower->change_interval.upper, 1100.2 * (1 + t) / (1000.0 * (1 - t)) - 1, 1e-12);
  EXPECT_LT(slower->change_interval.lower, slower->change);
  EXPECT_GT(slower->change_interval.upper, slower->change);
  EXPECT_EQ(classify_change(*slower, 0.01), ChangeVerdict::regressed);

  const auto same = exact_change(rounds({1000.0, 1000.4}, {1000.2, 999.9}));
  ASSERT_TRUE(same);
  EXPECT_EQ(classify_change(*same, 0.01), ChangeVerdict::unchanged);
  const std::string text = change_with_interval(*same, ChangeVerdict::unchanged, 0.01);
  EXPECT_NE(text.find("] counted (simulated cycles)"), std::string::npos) << text;

  // Near the limit the bound reaches across it: no verdict from counts, however many rounds.
  const auto at_limit = exact_change(rounds({1000.0, 1000.9}, {1010.0, 1010.0}));
  ASSERT_TRUE(at_limit);
  EXPECT_LT(at_limit->change_interval.lower, 0.01);
  EXPECT_GT(at_limit->change_interval.upper, 0.01);
  EXPECT_EQ(classify_change(*at_limit, 0.01), ChangeVerdict::inconclusive);
}

TEST(SimulatedCost, RunCostsIdenticalNeedsTwoEqualRounds) {
  EXPECT_TRUE(costs_identical(std::vector<RoundSample>{{5.0, 7.0}, {5.0, 7.0}}));
  EXPECT_FALSE(costs_identical(std::vector<RoundSample>{{5.0, 7.0}}));
  EXPECT_FALSE(costs_identical(std::vector<RoundSample>{{5.0, 7.0}, {5.0, 7.5}}));
}

TEST(SimulatedCost, RelativeSpreadIsMaxOverMin) {
  EXPECT_EQ(relative_spread(std::vector<double>{3.0, 3.0}), 0.0);
  EXPECT_DOUBLE_EQ(relative_spread(std::vector<double>{100.0, 101.0, 100.5}), 0.01);
}

}  // namespace
}  // namespace raygate

// The sim mode's cost model and its exact verdicts: the documented weights, the counters' JSON,
// and that rounds whose counts all repeat give an exact change (0 for A/A, a decided verdict
// after two rounds), while rounds that differ give none (the caller falls back to statistics).
#include "measure/simulated_cost.h"

#include <gtest/gtest.h>

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
  EXPECT_FALSE(exact_change(rounds({1000.0, 1000.5}, {1010.0, 1010.0})));
  EXPECT_FALSE(exact_change(rounds({1000.0, 1000.0}, {1010.0, 1011.0})));
  std::vector<CompareRound> baseline_moved = rounds({1000.0, 1000.0}, {1010.0, 1010.0});
  baseline_moved[1].baseline_seconds = 1001.0;
  EXPECT_FALSE(exact_change(baseline_moved));
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

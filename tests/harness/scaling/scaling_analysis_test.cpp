// The scaling analysis of results documents built by hand: families grouped and fitted, the
// compare's exponent change judged and projected, the JSON round trip, and the growth gate.
#include "scaling/scaling_analysis.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "gate/growth_gate.h"
#include "results/scaling_json.h"
#include "scaling/scaling_text.h"

namespace raygate {
namespace {

// balls' primitive counts per size factor: (9^(s+1) - 1) / 8 spheres and the floor polygon.
std::int64_t balls_count(const std::string& scene, int size) {
  EXPECT_EQ(scene, "balls");
  return static_cast<std::int64_t>(std::lround((std::pow(9.0, size + 1) - 1) / 8)) + 1;
}

RatioSummary ratio(double tracer, double baseline) {
  RatioSummary r;
  r.tracer_median_seconds = tracer;
  r.baseline_median_seconds = baseline;
  r.ratio = tracer / baseline;
  r.rounds = 6;
  return r;
}

// balls at sizes 1..4; the baseline linear, base growing as n^0.2, head as n^(0.2 + extra),
// times `added(n)` when given (head = base · added(n)); each change measured to ±2%.
ResultsDocument compare_document(double extra, int sizes = 4, double (*added)(double) = nullptr) {
  ResultsDocument d;
  d.kind = DocumentKind::compare;
  d.suite = "scaling";
  d.revisions.resize(2);
  d.revisions[0].role = Role::base;
  d.revisions[1].role = Role::head;
  for (int size = 1; size <= sizes; ++size) {
    const double n = static_cast<double>(balls_count("balls", size));
    SceneResult s;
    s.entry = {"balls-s" + std::to_string(size), "balls", size, 64, 64};
    s.status = SceneStatus::measured;
    const double baseline = 1e-4 * n, base = 0.01 * std::pow(n, 0.2),
                 head = 0.01 * std::pow(n, 0.2 + extra) * (added ? added(n) : 1.0);
    s.ratios[Role::base] = ratio(base, baseline);
    s.ratios[Role::head] = ratio(head, baseline);
    s.change = ChangeSummary{};
    s.change->change = head / base - 1;
    s.change->change_interval = {s.change->change - 0.02, s.change->change + 0.02};
    d.scenes.push_back(s);
  }
  // A family measured at one size only: not fitted.
  SceneResult lone;
  lone.entry = {"tetra", "tetra", 3, 64, 64};
  lone.status = SceneStatus::measured;
  lone.ratios[Role::base] = ratio(0.1, 0.2);
  lone.ratios[Role::head] = ratio(0.1, 0.2);
  d.scenes.push_back(lone);
  return d;
}

TEST(ScalingAnalysisTest, FitsEachFamilyForBaselineRolesAndRatios) {
  const ScalingAnalysis a = analyse_scaling(compare_document(0.0), {}, balls_count);
  ASSERT_EQ(a.families.size(), 1u);  // tetra has one size
  const FamilyScaling& balls = a.families[0];
  EXPECT_EQ(balls.family, "balls");
  ASSERT_EQ(balls.points.size(), 4u);
  EXPECT_EQ(balls.points[3].primitives, 7382);
  EXPECT_NEAR(balls.baseline.exponent, 1.0, 1e-9);
  EXPECT_NEAR(balls.roles.at(Role::base).time.exponent, 0.2, 1e-9);
  EXPECT_NEAR(balls.roles.at(Role::head).ratio.exponent, -0.8, 1e-9);
  EXPECT_EQ(balls.series_id.size(), 16u);
}

TEST(ScalingAnalysisTest, UnchangedGrowthPassesWithoutProjection) {
  const ScalingAnalysis a = analyse_scaling(compare_document(0.0), {}, balls_count);
  ASSERT_TRUE(a.families[0].change);
  EXPECT_EQ(a.families[0].change->verdict, ChangeVerdict::unchanged);
  EXPECT_FALSE(a.families[0].change->crossing);
}

TEST(ScalingAnalysisTest, SteeperHeadRegressesAndIsProjected) {
  ScalingLimits limits;
  limits.max_exponent_increase = 0.1;
  limits.max_slowdown = 0.03;
  const ScalingAnalysis a = analyse_scaling(compare_document(0.3), limits, balls_count);
  const ExponentChange& c = *a.families[0].change;
  EXPECT_NEAR(c.fit.exponent, 0.3, 1e-9);
  EXPECT_EQ(c.verdict, ChangeVerdict::regressed);
  // head/base = n^0.3 exceeds 1.03 from the smallest size on.
  ASSERT_TRUE(c.crossing);
  EXPECT_EQ(c.crossing->size, 1);
  ASSERT_TRUE(c.largest);
  EXPECT_EQ(c.largest->size, 6);  // balls' largest size factor
  EXPECT_NEAR(c.largest->change, std::pow(597872.0, 0.3) - 1, 1e-6);
  const std::string text = describe_change("balls", c);
  EXPECT_NE(text.find("REGRESSED"), std::string::npos) << text;
  EXPECT_NE(text.find("at balls size 6 (597872 primitives) head is projected"), std::string::npos)
      << text;
}

TEST(ScalingAnalysisTest, AddedLinearWorkBehindAFixedCostIsJudgedAtTheLargeEnd) {
  // head = base + 0.1% of base per primitive: flat at 11 primitives, 8x at 7382. A line through
  // all four sizes averages the flat part in; the two largest sizes show the growth.
  const ScalingAnalysis a = analyse_scaling(
      compare_document(0.0, 4, [](double n) { return 1 + 1e-3 * n; }), {}, balls_count);
  const ExponentChange& c = *a.families[0].change;
  EXPECT_NE(c.fit.quality, FitQuality::power_law);
  ASSERT_TRUE(c.large_end);
  const double expected =
      (std::log(1 + 1e-3 * 7382) - std::log(1 + 1e-3 * 821)) / (std::log(7382.0) - std::log(821.0));
  EXPECT_NEAR(c.large_end->exponent, expected, 1e-9);
  EXPECT_GT(c.large_end->exponent, c.fit.exponent);
  // The interval: the widest slope the two sizes' ±2% intervals allow.
  const double step = std::log(7382.0) - std::log(821.0);
  EXPECT_NEAR(c.large_end->exponent_interval.lower,
              (std::log(1 + 1e-3 * 7382 - 0.02) - std::log(1 + 1e-3 * 821 + 0.02)) / step, 1e-9);
  EXPECT_EQ(c.verdict, ChangeVerdict::regressed);
  EXPECT_NE(describe_change("balls", c).find("between the two largest sizes"), std::string::npos);
  // Stored and read back, the gate judges the same slope.
  ResultsDocument d = compare_document(0.0, 4, [](double n) { return 1 + 1e-3 * n; });
  d.scaling = scaling_from_json(JsonField(to_json(a), "$.scaling"));
  EXPECT_EQ(judge_growth(d, GatePolicy{})[0].outcome, GateOutcome::fail);
}

TEST(ScalingAnalysisTest, ARunHasNoChange) {
  ResultsDocument d = compare_document(0.0);
  d.kind = DocumentKind::run;
  for (SceneResult& s : d.scenes) {
    s.ratios = {{Role::tracer, s.ratios.at(Role::base)}};
    s.change.reset();
  }
  const ScalingAnalysis a = analyse_scaling(d, {}, balls_count);
  ASSERT_EQ(a.families.size(), 1u);
  EXPECT_FALSE(a.families[0].change);
  EXPECT_FALSE(worst_exponent_verdict(a));
}

TEST(ScalingAnalysisTest, FailedScenesLeaveTheFamilyAndTooFewSizesDropIt) {
  ResultsDocument d = compare_document(0.0, 3);
  d.scenes[1].status = SceneStatus::failed;
  EXPECT_TRUE(analyse_scaling(d, {}, balls_count).families.empty());
}

TEST(ScalingAnalysisTest, JsonRoundTripKeepsEverything) {
  const ScalingAnalysis a = analyse_scaling(compare_document(0.3), {}, balls_count);
  const nlohmann::json j = to_json(a);
  const ScalingAnalysis back = scaling_from_json(JsonField(j, "$.scaling"));
  EXPECT_EQ(to_json(back), j);
  const nlohmann::json bad{{"max_exponent_increase", 0.1}, {"families", 3}};
  try {
    scaling_from_json(JsonField(bad, "$.scaling"));
    ADD_FAILURE() << "accepted " << bad.dump();
  } catch (const FieldError& e) {
    EXPECT_EQ(e.path(), "$.scaling.families");
  }
}

TEST(GrowthGateTest, JudgesTheStoredFitUnderThePolicyLimit) {
  ResultsDocument d = compare_document(0.3);
  d.scaling = analyse_scaling(d, {}, balls_count);
  GatePolicy policy;
  std::vector<SceneGate> gates = judge_growth(d, policy);
  ASSERT_EQ(gates.size(), 1u);
  EXPECT_EQ(gates[0].id, "scaling:balls");
  EXPECT_EQ(gates[0].outcome, GateOutcome::fail);
  ASSERT_EQ(gates[0].reasons.size(), 1u);
  EXPECT_NE(gates[0].reasons[0].find("+0.30"), std::string::npos) << gates[0].reasons[0];
  policy.max_exponent_increase = 0.5;  // a looser policy judges the same fit again
  EXPECT_EQ(judge_growth(d, policy)[0].outcome, GateOutcome::pass);
  EXPECT_TRUE(judge_growth(compare_document(0.3), policy).empty());  // no analysis stored
}

TEST(GrowthGateTest, ARegressedExponentFailsTheWholeGate) {
  ResultsDocument d = compare_document(0.3);
  d.complete = true;
  d.scaling = analyse_scaling(d, {}, balls_count);
  for (SceneResult& s : d.scenes) s.change_verdict = ChangeVerdict::unchanged;
  const GateResult gate = evaluate_gate(d, GatePolicy{});
  EXPECT_EQ(gate.exit_code, 1);
  ASSERT_EQ(gate.families.size(), 1u);
}

}  // namespace
}  // namespace raygate

namespace raygate {
namespace {

TEST(GrowthPolicyTest, MaxExponentIncreaseIsReadAndChecked) {
  EXPECT_DOUBLE_EQ(GatePolicy{}.max_exponent_increase, 0.1);
  EXPECT_DOUBLE_EQ(
      parse_policy(R"({"max_exponent_increase": 0.25})", "p.json").max_exponent_increase, 0.25);
  EXPECT_THROW(parse_policy(R"({"max_exponent_increase": -1})", "p.json"), UsageError);
  std::string note;
  MeasurementSettings settings;
  settings.max_exponent_increase = 0.4;
  EXPECT_DOUBLE_EQ(recorded_policy(settings, note).max_exponent_increase, 0.4);
}

}  // namespace
}  // namespace raygate

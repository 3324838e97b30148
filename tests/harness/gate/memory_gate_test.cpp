// The memory rule (measure/memory_change.h), the policy's max_memory_increase, and the gate on
// hand-made compare documents whose runs carry their own peaks (gate/memory_gate.h).
#include "gate/memory_gate.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "gate/verdict.h"

namespace raygate {
namespace {

constexpr long kMib = 1024;

ChangeVerdict verdict(std::vector<long> base, std::vector<long> head, double limit = 0.10) {
  return classify_memory(*summarize_memory(base, head), limit);
}

TEST(MemoryRule, MediansDeltaAndNoise) {
  const MemorySummary s = *summarize_memory(std::vector<long>{100 * kMib, 102 * kMib, 101 * kMib},
                                            std::vector<long>{150 * kMib, 151 * kMib});
  EXPECT_DOUBLE_EQ(s.base_kib, 101 * kMib);
  EXPECT_DOUBLE_EQ(s.head_kib, 150.5 * kMib);
  EXPECT_DOUBLE_EQ(s.delta_kib, 49.5 * kMib);
  EXPECT_DOUBLE_EQ(s.floor_kib, 0.02 * 101 * kMib);  // 2% of base beats 1 MiB here
  EXPECT_DOUBLE_EQ(s.spread_kib, 2 * kMib);
  EXPECT_DOUBLE_EQ(s.noise_kib(), 2.02 * kMib);
  EXPECT_FALSE(summarize_memory(std::vector<long>{}, std::vector<long>{1}).has_value());
}

TEST(MemoryRule, VerdictsAgainstTheLimitAndTheNoise) {
  // +50 MiB on an 8 MiB tracer: REGRESSED; its mirror IMPROVED.
  EXPECT_EQ(verdict({8 * kMib, 8 * kMib}, {58 * kMib, 58 * kMib}), ChangeVerdict::regressed);
  EXPECT_EQ(verdict({58 * kMib, 58 * kMib}, {8 * kMib, 8 * kMib}), ChangeVerdict::improved);
  // A/A: a few hundred KiB of jitter is UNCHANGED, even where 10% of base is under 1 MiB.
  EXPECT_EQ(verdict({5 * kMib, 5 * kMib + 300}, {5 * kMib + 200, 5 * kMib}),
            ChangeVerdict::unchanged);
  // +0.9 MiB on 5 MiB is +18% but under the 1 MiB floor: not judged a regression.
  EXPECT_EQ(verdict({5 * kMib}, {5 * kMib + 900}), ChangeVerdict::unchanged);
  // +5% on 100 MiB, steady: within the limit.
  EXPECT_EQ(verdict({100 * kMib, 100 * kMib}, {105 * kMib, 105 * kMib}), ChangeVerdict::unchanged);
  // The same +5% while base's peaks spread by 20 MiB: a change of the limit's size could hide.
  EXPECT_EQ(verdict({90 * kMib, 100 * kMib, 110 * kMib}, {105 * kMib}),
            ChangeVerdict::inconclusive);
  // +15% beyond the limit but inside that 20 MiB spread: not a regression either.
  EXPECT_EQ(verdict({90 * kMib, 100 * kMib, 110 * kMib}, {115 * kMib}),
            ChangeVerdict::inconclusive);
  EXPECT_EQ(verdict({90 * kMib, 100 * kMib, 110 * kMib}, {125 * kMib}), ChangeVerdict::regressed);
  // A looser limit lets +50% pass.
  EXPECT_EQ(verdict({100 * kMib}, {150 * kMib}, 0.6), ChangeVerdict::unchanged);
}

TEST(MemoryPolicy, ParsesTheLimitAndPerSceneOverrides) {
  const GatePolicy p = parse_policy(
      R"({"max_memory_increase": 0.25, "scenes": {"big": {"max_memory_increase": 1.0,
          "reason": "the texture cache is meant to grow"}}})",
      "policy.json");
  EXPECT_DOUBLE_EQ(p.defaults.max_memory_increase, 0.25);
  EXPECT_DOUBLE_EQ(p.for_scene("big").max_memory_increase, 1.0);
  EXPECT_DOUBLE_EQ(GatePolicy{}.defaults.max_memory_increase, 0.10);
  try {
    parse_policy(R"({"max_memory_increase": -1})", "policy.json");
    FAIL() << "a negative limit was accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("$.max_memory_increase"), std::string::npos) << e.what();
  }
}

RunRecord run_with_peak(long kib, bool own = true) {
  RunRecord run;
  run.ok = true;
  run.seconds = 1.0;
  run.max_rss_kib = kib;
  run.max_rss_own = own;
  return run;
}

SceneResult compare_scene(const std::string& id, long base_kib, long head_kib, bool own = true) {
  SceneResult scene;
  scene.entry.id = id;
  scene.status = SceneStatus::measured;
  for (int i = 0; i < 3; ++i) {
    Round round;
    round.order = {"base", "head"};
    round.runs["base"] = run_with_peak(base_kib + i, own);
    round.runs["head"] = run_with_peak(head_kib + i, own);
    scene.runs.rounds.push_back(round);
  }
  ChangeSummary change;
  change.rounds = 3;
  change.exact = true;  // judged by its change alone: 0, UNCHANGED
  scene.change = change;
  scene.change_verdict = ChangeVerdict::unchanged;
  return scene;
}

ResultsDocument compare_document(std::vector<SceneResult> scenes) {
  ResultsDocument d;
  d.kind = DocumentKind::compare;
  d.complete = true;
  d.scenes = std::move(scenes);
  return d;
}

TEST(MemoryGate, MoreMemoryFailsTheSceneWithItsNumbers) {
  const GateResult gate =
      evaluate_gate(compare_document({compare_scene("grown", 8 * kMib, 58 * kMib),
                                      compare_scene("same", 8 * kMib, 8 * kMib)}),
                    GatePolicy{});
  EXPECT_EQ(gate.exit_code, 1);
  ASSERT_EQ(gate.scenes.size(), 2u);
  EXPECT_EQ(gate.scenes[0].memory, ChangeVerdict::regressed);
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::fail);
  ASSERT_FALSE(gate.scenes[0].reasons.empty());
  EXPECT_NE(gate.scenes[0].reasons[0].find("more memory: head 58.0 MiB vs base 8.0 MiB "
                                           "(+50.0 MiB, +624.9%), limit +10%"),
            std::string::npos)
      << gate.scenes[0].reasons[0];
  EXPECT_EQ(gate.scenes[1].memory, ChangeVerdict::unchanged);
  EXPECT_EQ(gate.scenes[1].outcome, GateOutcome::pass);
}

TEST(MemoryGate, PeaksThatAreNotTheTracersOwnAreNotJudged) {
  // Documents from before raygate-meter hold raygate's peak in every run: no memory verdict.
  const GateResult gate = evaluate_gate(
      compare_document({compare_scene("old", 130 * kMib, 190 * kMib, false)}), GatePolicy{});
  EXPECT_EQ(gate.exit_code, 0);
  EXPECT_FALSE(gate.scenes[0].memory.has_value());
}

}  // namespace
}  // namespace raygate

// The gate: policy files (defaults, per-scene overrides that must give a reason, errors that
// name the JSON path) and the verdict on a document (which scene fails, warns or could not be
// measured, the reason lines, and the exit code 0 / 1 / 3).
#include <gtest/gtest.h>

#include "core/error.h"
#include "gate/policy.h"
#include "gate/verdict.h"

namespace raygate {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_policy(text, "policy.json");
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no error";
}

TEST(GatePolicy, DefaultsWithoutAFile) {
  const GatePolicy policy = parse_policy("{}", "policy.json");
  EXPECT_DOUBLE_EQ(policy.defaults.max_slowdown, 0.03);
  EXPECT_DOUBLE_EQ(policy.defaults.significance, 0.05);
  EXPECT_DOUBLE_EQ(policy.defaults.image.fail_threshold, 0.004);
  EXPECT_FALSE(policy.fail_on_inconclusive);
}

TEST(GatePolicy, SceneOverridesInheritTheDefaultsTheyDoNotSet) {
  const GatePolicy policy = parse_policy(R"({
    "max_slowdown": 0.05, "image": {"fail": 0.01},
    "scenes": {"mount": {"image": {"failpercent": 0.5}, "reason": "terrain noise"}}})",
                                         "policy.json");
  const ScenePolicy& mount = policy.for_scene("mount");
  EXPECT_DOUBLE_EQ(mount.max_slowdown, 0.05);
  EXPECT_DOUBLE_EQ(mount.image.fail_threshold, 0.01);
  EXPECT_DOUBLE_EQ(mount.image.fail_percent, 0.5);
  EXPECT_EQ(mount.reason, "terrain noise");
  EXPECT_DOUBLE_EQ(policy.for_scene("balls").image.fail_percent, 0.02);
}

TEST(GatePolicy, MistakesNameTheJsonPath) {
  EXPECT_EQ(error_of(R"({"max_slowdwn": 0.1})"),
            "policy.json: $.max_slowdwn: unknown key 'max_slowdwn' (did you mean "
            "'max_slowdown'?)");
  EXPECT_EQ(error_of(R"({"max_slowdown": -1})"),
            "policy.json: $.max_slowdown: must be between 0 and 10, found -1");
  EXPECT_EQ(error_of(R"({"scenes": {"mount": {"max_slowdown": 0.06}}})"),
            "policy.json: $.scenes.mount: missing required key 'reason'");
  EXPECT_EQ(error_of(R"({"scenes": {"mount": {"max_slowdown": 0.06, "reason": ""}}})"),
            "policy.json: $.scenes.mount.reason: must say why this scene differs");
  EXPECT_NE(error_of("{bad").find("policy.json:1:2: not JSON"), std::string::npos);
}

// Issue 25: "max_slowdown": 0.03, "max_slowdown": 5 gated at +500%, and 1e400 was an internal
// error. Both are refused with the file, line, column and JSON path.
TEST(GatePolicy, ADuplicateKeyOrAnOutOfRangeNumberIsRefusedWhereItIs) {
  EXPECT_EQ(error_of(R"({"max_slowdown": 0.03, "max_slowdown": 5})"),
            "policy.json:1:24: $: duplicate key 'max_slowdown' (JSON keeps only one of them; "
            "remove the other)");
  EXPECT_EQ(error_of(R"({"image": {"fail": 0.01, "fail": 0.5}})"),
            "policy.json:1:26: $.image: duplicate key 'fail' (JSON keeps only one of them; "
            "remove the other)");
  EXPECT_NE(error_of(R"({"scenes": {"balls": {"reason": "noisy", "max_slowdown": 1e400}}})")
                .find("policy.json:1:58: $.scenes.balls.max_slowdown: number 1e400 is out of "
                      "range"),
            std::string::npos);
}

// A compare scene whose head changed by `change` with the CI [lower, upper] over `rounds`.
SceneResult compared(const std::string& id, double change, double lower, double upper,
                     std::size_t rounds = 10) {
  SceneResult scene;
  scene.entry.id = id;
  scene.status = SceneStatus::measured;
  scene.change = ChangeSummary{};
  scene.change->change = change;
  scene.change->change_interval = {lower, upper};
  scene.change->rounds = rounds;
  return scene;
}

ResultsDocument compare_document(std::vector<SceneResult> scenes) {
  ResultsDocument document;
  document.kind = DocumentKind::compare;
  document.complete = true;
  document.scenes = std::move(scenes);
  return document;
}

TEST(GateVerdict, TooFewRoundsDecideNothing) {
  // Five rounds cannot give a 95% interval for a median: whatever the numbers, INCONCLUSIVE.
  const GateResult gate =
      evaluate_gate(compare_document({compared("tetra", 0.40, 0.002, 0.45, 5)}), GatePolicy{});
  EXPECT_EQ(gate.scenes[0].speed, SpeedVerdict::inconclusive);
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::warn);
  EXPECT_EQ(gate.exit_code, 0);
}

TEST(GateVerdict, RegressionFailsWithItsNumbers) {
  const GateResult gate = evaluate_gate(compare_document({compared("mount", 0.079, 0.061, 0.098),
                                                          compared("balls", 0.004, -0.006, 0.013)}),
                                        GatePolicy{});
  EXPECT_EQ(gate.exit_code, 1);
  ASSERT_EQ(gate.scenes.size(), 2u);
  EXPECT_EQ(gate.scenes[0].speed, SpeedVerdict::regressed);
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::fail);
  ASSERT_EQ(gate.scenes[0].reasons.size(), 1u);
  EXPECT_NE(gate.scenes[0].reasons[0].find("+7.9% [+6.1%, +9.8%] 95% CI"), std::string::npos)
      << gate.scenes[0].reasons[0];
  EXPECT_EQ(gate.scenes[1].speed, SpeedVerdict::unchanged);
  EXPECT_EQ(gate.scenes[1].outcome, GateOutcome::pass);
}

TEST(GateVerdict, APerSceneLimitDecides) {
  GatePolicy policy;
  policy.scenes["mount"] = policy.defaults;
  policy.scenes["mount"].max_slowdown = 0.10;
  policy.scenes["mount"].reason = "noisy";
  const GateResult gate =
      evaluate_gate(compare_document({compared("mount", 0.079, 0.061, 0.098)}), policy);
  EXPECT_EQ(gate.exit_code, 0);
  EXPECT_EQ(gate.scenes[0].speed, SpeedVerdict::unchanged);
}

TEST(GateVerdict, InconclusiveWarnsUnlessTheFlagSaysFail) {
  const ResultsDocument document = compare_document({compared("tetra", 0.02, -0.01, 0.05)});
  GatePolicy policy;
  GateResult gate = evaluate_gate(document, policy);
  EXPECT_EQ(gate.scenes[0].speed, SpeedVerdict::inconclusive);
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::warn);
  EXPECT_EQ(gate.exit_code, 0);
  policy.fail_on_inconclusive = true;
  gate = evaluate_gate(document, policy);
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::fail);
  EXPECT_EQ(gate.exit_code, 1);
}

// A compare scene on confidence sequences: its change, equivalence sequence and rounds' spread.
SceneResult sequenced(const std::string& id, double change, Interval equivalence,
                      std::size_t rounds, double spread) {
  SceneResult scene = compared(id, change, -0.5, 0.5, rounds);
  ChangeSummary& c = *scene.change;
  c.interval_kind = ChangeIntervalKind::confidence_sequence;
  c.confidence = 0.9985;
  c.equivalence_interval = equivalence;
  c.equivalence_confidence = 0.90;
  c.one_look_interval = {-0.5, 0.5};
  c.one_look_confidence = 0.95;
  c.log_change_mad_scaled = spread;
  return scene;
}

TEST(GateVerdict, AnUndecidedCompareSaysHowNoisyTheRunnerWas) {
  // Two scenes decided, one not: the note gives the median spread of all three and, at their
  // typical 10 rounds (the 90% sequence is the rounds' range, about +-1.55 sigma), what the
  // spread would have had to be below: ln(1.03) / 1.546 = 1.9%.
  const ResultsDocument document =
      compare_document({sequenced("balls", 0.0, {-0.01, 0.01}, 10, 0.004),
                        sequenced("gears", 0.0, {-0.02, 0.02}, 10, 0.041),
                        sequenced("mount", 0.01, {-0.09, 0.12}, 12, 0.089)});
  const GateResult gate = evaluate_gate(document, GatePolicy{});
  EXPECT_EQ(gate.exit_code, 0);
  ASSERT_EQ(gate.notes.size(), 1u);
  EXPECT_EQ(gate.notes[0],
            "runner noise: the rounds of a scene differed by 4.1% (head/base per round, scaled "
            "MAD, median of 3 scenes); in the 10 rounds a scene typically got, an unchanged scene "
            "is shown within the 3.0% limit (UNCHANGED) only when its rounds differ by less than "
            "about 1.9%. A quieter runner or a longer "
            "--max-minutes decides more; raygate doctor measures a runner's noise.");
  // Nothing to say when every scene is decided, or for documents before confidence sequences.
  EXPECT_TRUE(evaluate_gate(compare_document({sequenced("balls", 0.0, {-0.01, 0.01}, 10, 0.004)}),
                            GatePolicy{})
                  .notes.empty());
  EXPECT_TRUE(evaluate_gate(compare_document({compared("tetra", 0.02, -0.01, 0.05)}), GatePolicy{})
                  .notes.empty());
}

// The sweep of 2026-11-28: a policy's override for a misspelt scene had no effect, unsaid.
TEST(GateVerdict, APolicyOverrideForNoSceneOfTheDocumentIsNoted) {
  const ResultsDocument document =
      compare_document({sequenced("balls", 0.0, {-0.01, 0.01}, 10, 0.004)});
  GatePolicy policy;
  policy.scenes["balls"] = policy.defaults;
  EXPECT_TRUE(evaluate_gate(document, policy).notes.empty());
  policy.scenes["ballz"] = policy.defaults;
  const GateResult gate = evaluate_gate(document, policy);
  ASSERT_EQ(gate.notes.size(), 1u);
  EXPECT_EQ(gate.notes[0],
            "the policy's overrides for 'ballz' match no scene of this document: no effect here");
  EXPECT_EQ(gate.exit_code, 0);
}

SceneResult failed(const std::string& id, Role role, bool base_ran) {
  SceneResult scene;
  scene.entry.id = id;
  scene.status = SceneStatus::failed;
  RunRecord crash;
  crash.outcome = "killed by signal 6 (ABRT)";
  crash.failure = "tracer killed by signal 6 (ABRT)";
  scene.runs.failed_role = role;
  scene.runs.failed_run = crash;
  if (base_ran) {
    RunRecord ok;
    ok.ok = true;
    scene.runs.warmup["base"].push_back(ok);
  }
  return scene;
}

TEST(GateVerdict, HeadCrashingWhereBaseRanIsTheChangesFault) {
  const GateResult gate =
      evaluate_gate(compare_document({failed("balls", Role::head, true)}), GatePolicy{});
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::fail);
  EXPECT_NE(gate.scenes[0].reasons[0].find("head failed where base ran"), std::string::npos);
  EXPECT_NE(gate.scenes[0].reasons[0].find(": head: tracer killed by signal 6 (ABRT) (log: "),
            std::string::npos)
      << gate.scenes[0].reasons[0];
  EXPECT_EQ(gate.exit_code, 1);
}

// The tenth sweep: raygate's own budget (--max-seconds 2.5) cut off head's run of an A/A compare,
// and the gate called it "tetra crashed", exit 1. The budget's cut says nothing of head.
TEST(GateVerdict, HeadStoppedByTheBudgetIsNotMeasuredNotRegressed) {
  SceneResult scene = failed("tetra", Role::head, true);
  scene.runs.failed_run->outcome = "timed out after 2.5 s";
  scene.runs.failed_run->stopped_by_budget = true;
  const GateResult gate = evaluate_gate(compare_document({scene}), GatePolicy{});
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::unmeasured);
  EXPECT_EQ(gate.scenes[0].reasons[0].find("head failed where base ran"), std::string::npos);
  EXPECT_EQ(gate.exit_code, 3);
}

// The sweep of 2026-11-28: "baseline exited with status 0: raygate-baseline took no measurable
// process-user time" read as if the exit status were the problem.
TEST(GateVerdict, ARunThatEndedWellAndFailedAfterSaysBut) {
  SceneResult scene = failed("tetra", Role::baseline, false);
  scene.runs.failed_run->outcome = "exited with status 0";
  scene.runs.failed_run->failure = "raygate-baseline took no measurable process-user time";
  const GateResult gate = evaluate_gate(compare_document({scene}), GatePolicy{});
  EXPECT_NE(gate.scenes[0].reasons[0].find("baseline exited with status 0, but raygate-baseline "
                                           "took no measurable process-user time (log: "),
            std::string::npos)
      << gate.scenes[0].reasons[0];
  EXPECT_EQ(gate.exit_code, 3);
}

TEST(GateVerdict, BaseOrBaselineFailingMeansNotMeasured) {
  for (const Role role : {Role::base, Role::baseline}) {
    const GateResult gate =
        evaluate_gate(compare_document({failed("balls", role, false)}), GatePolicy{});
    EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::unmeasured) << to_string(role);
    EXPECT_EQ(gate.exit_code, 3) << to_string(role);
  }
}

TEST(GateVerdict, ARegressionOutranksAnUnmeasuredScene) {
  const GateResult gate = evaluate_gate(
      compare_document({failed("balls", Role::base, false), compared("mount", 0.2, 0.15, 0.25)}),
      GatePolicy{});
  EXPECT_EQ(gate.exit_code, 1);
  EXPECT_EQ(gate.count(GateOutcome::unmeasured), 1u);
  EXPECT_EQ(gate.count(GateOutcome::fail), 1u);
}

// A Monte Carlo image neither shown within its tolerance nor beyond it is inconclusive, like a
// speed change the budget could not decide: a warning (exit 0), a failure with
// fail_on_inconclusive; the report says the comparison's line.
TEST(GateVerdict, AnInconclusiveMonteCarloImageWarnsOrFailsAsPolicySays) {
  SceneResult scene = compared("gears", 0.0, -0.01, 0.01);
  ImageCheck check{
      Role::head, ImageReference::base, "a.exr", "b.exr",          ImageVerdict::inconclusive,
      "",         std::nullopt,         {},      NoisyComparison{}};
  check.noisy->tests = 123;
  check.noisy->image = {-0.0203, -0.0342, -0.0064};
  check.noisy->samples_factor = 2.0;
  check.noisy->runs_needed = 60;
  check.noisy->why_inconclusive = "the whole image is shown neither within nor beyond";
  scene.images = {check};
  GateResult gate = evaluate_gate(compare_document({scene}), GatePolicy{});
  EXPECT_EQ(gate.scenes[0].image, ImageVerdict::inconclusive);
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::warn);
  EXPECT_EQ(gate.exit_code, 0);
  GatePolicy strict;
  strict.fail_on_inconclusive = true;
  gate = evaluate_gate(compare_document({scene}), strict);
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::fail);
  EXPECT_EQ(gate.exit_code, 1);
}

TEST(GatePolicyFile, TheImageToleranceIsReadAndChecked) {
  const GatePolicy policy = parse_policy(
      R"({"image_tolerance": 0.02, "scenes": {"gears": {"image_tolerance": 0.03, "reason": "caustics"}}})",
      "p.json");
  EXPECT_DOUBLE_EQ(policy.defaults.image_tolerance, 0.02);
  EXPECT_DOUBLE_EQ(policy.for_scene("gears").image_tolerance, 0.03);
  EXPECT_DOUBLE_EQ(GatePolicy{}.defaults.image_tolerance, 0.01);
  EXPECT_THROW(parse_policy(R"({"image_tolerance": 0})", "p.json"), UsageError);
  EXPECT_THROW(parse_policy(R"({"image_tolerance": -0.01})", "p.json"), UsageError);
}

TEST(GateVerdict, ImagesFailWarnOrCannotBeChecked) {
  SceneResult scene = compared("gears", 0.0, -0.01, 0.01);
  ImageMetrics metrics;
  metrics.max_error = 0.6;
  scene.images.push_back({Role::head,
                          ImageReference::golden,
                          "a.png",
                          "g.png",
                          ImageVerdict::fail,
                          "",
                          metrics,
                          {},
                          std::nullopt});
  scene.images.push_back({Role::head,
                          ImageReference::base,
                          "a.png",
                          "b.png",
                          ImageVerdict::pass,
                          "",
                          ImageMetrics{},
                          {},
                          std::nullopt});
  GateResult gate = evaluate_gate(compare_document({scene}), GatePolicy{});
  EXPECT_EQ(gate.scenes[0].image, ImageVerdict::fail);
  EXPECT_EQ(gate.exit_code, 1);

  scene.images = {{Role::tracer,
                   ImageReference::golden,
                   "a.png",
                   "g.png",
                   ImageVerdict::missing,
                   "no golden image",
                   {},
                   {},
                   std::nullopt}};
  gate = evaluate_gate(compare_document({scene}), GatePolicy{});
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::pass);  // a note for the document, not a warning
  EXPECT_EQ(gate.exit_code, 0);

  scene.images = {{Role::tracer,
                   ImageReference::golden,
                   "a.png",
                   "g.png",
                   ImageVerdict::error,
                   "cannot read a.png",
                   {},
                   {},
                   std::nullopt}};
  gate = evaluate_gate(compare_document({scene}), GatePolicy{});
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::unmeasured);
  EXPECT_EQ(gate.exit_code, 3);
}

TEST(GateVerdict, AnIncompleteDocumentCannotPass) {
  ResultsDocument document = compare_document({compared("tetra", 0.0, -0.01, 0.01)});
  document.complete = false;
  const GateResult gate = evaluate_gate(document, GatePolicy{});
  EXPECT_EQ(gate.exit_code, 3);
  ASSERT_EQ(gate.problems.size(), 1u);
  EXPECT_EQ(gate.problems[0],
            "the document is incomplete: it holds 1 scene (its run stopped early, or a merge "
            "lacked shards)");
}

// Nothing measured is not a pass, complete or not.
TEST(GateVerdict, ADocumentWithNoScenesCannotPass) {
  for (const bool complete : {true, false}) {
    ResultsDocument document = compare_document({});
    document.complete = complete;
    const GateResult gate = evaluate_gate(document, GatePolicy{});
    EXPECT_EQ(gate.exit_code, 3);
    ASSERT_EQ(gate.problems.size(), 1u);
    EXPECT_EQ(gate.problems[0], "the document holds no scenes: nothing was measured");
  }
}

// A tracer without goldens: every scene's "no goldens" check becomes one note with the count
// and how to bless; no scene warns or fails for it. Different reasons stay apart.
TEST(GateVerdict, MissingGoldensAreOneNoteNotAWarningPerScene) {
  const ImageCheck none{Role::head,
                        ImageReference::golden,
                        "a.png",
                        "g",
                        ImageVerdict::missing,
                        "no goldens in g (none blessed yet)",
                        {},
                        {},
                        std::nullopt};
  const ImageCheck same{Role::head, ImageReference::base, "a.png", "b.png",     ImageVerdict::pass,
                        "",         ImageMetrics{},       {},      std::nullopt};
  std::vector<SceneResult> scenes;
  for (const char* id : {"balls", "gears", "tetra"}) {
    scenes.push_back(compared(id, 0.0, -0.01, 0.01));
    scenes.back().images = {none, same};
  }
  scenes.back().images.push_back({Role::base,
                                  ImageReference::golden,
                                  "b.png",
                                  "g",
                                  ImageVerdict::missing,
                                  "no golden image for 'tetra'",
                                  {},
                                  {},
                                  std::nullopt});
  const GateResult gate = evaluate_gate(compare_document(scenes), GatePolicy{});
  EXPECT_EQ(gate.exit_code, 0);
  EXPECT_EQ(gate.count(GateOutcome::pass), 3u);
  for (const SceneGate& scene : gate.scenes) {
    EXPECT_TRUE(scene.reasons.empty()) << scene.id;
    EXPECT_EQ(scene.image, ImageVerdict::pass) << scene.id;  // what was checked: head against base
  }
  ASSERT_EQ(gate.notes.size(), 2u);
  EXPECT_EQ(gate.notes[0],
            "images not checked against goldens: no goldens in g (none blessed yet) (3 scenes); "
            "look at the images, then bless them: raygate golden bless --from-run RESULTS.json "
            "--role head --golden-dir DIR (a folder kept with your tracer, then given to run and "
            "compare; without it, raygate's golden/<adapter>/)");
  EXPECT_NE(gate.notes[1].find("no golden image for 'tetra' (1 scene)"), std::string::npos)
      << gate.notes[1];
}

// Issue 40: a compare of 2 scenes without goldens said "(4 images)"; base and head each have an
// image per scene, and the note says so.
TEST(GateVerdict, MissingGoldensOfACompareCountScenesAndBothSides) {
  std::vector<SceneResult> scenes;
  for (const char* id : {"balls", "gears"}) {
    scenes.push_back(compared(id, 0.0, -0.01, 0.01));
    for (const Role role : {Role::base, Role::head}) {
      scenes.back().images.push_back({role,
                                      ImageReference::golden,
                                      "a.png",
                                      "g",
                                      ImageVerdict::missing,
                                      "no goldens in g (none blessed yet)",
                                      {},
                                      {},
                                      {}});
    }
  }
  const GateResult gate = evaluate_gate(compare_document(scenes), GatePolicy{});
  ASSERT_FALSE(gate.notes.empty());
  EXPECT_NE(gate.notes[0].find("(none blessed yet) (4 images: 2 scenes × base and head);"),
            std::string::npos)
      << gate.notes[0];
}

// A broken base image (NaN pixels, no goldens at all) is a reference that cannot be used: the
// change could not be checked (exit 3), it is not blamed on head (issue 25, class 8).
TEST(GateVerdict, ABrokenBaseImageCouldNotBeCheckedItIsNotTheChangesFault) {
  SceneResult scene = compared("gears", 0.0, -0.01, 0.01);
  scene.images = {{Role::base,
                   ImageReference::golden,
                   "b.png",
                   "g",
                   ImageVerdict::fail,
                   "b.png has 12 NaN pixels",
                   {},
                   {},
                   std::nullopt},
                  {Role::head,
                   ImageReference::base,
                   "a.png",
                   "b.png",
                   ImageVerdict::error,
                   "b.png: cannot compare",
                   {},
                   {},
                   std::nullopt}};
  const GateResult gate = evaluate_gate(compare_document({scene}), GatePolicy{});
  EXPECT_EQ(gate.exit_code, 3);
  ASSERT_EQ(gate.scenes.size(), 1u);
  EXPECT_EQ(gate.scenes[0].outcome, GateOutcome::unmeasured);
  ASSERT_FALSE(gate.scenes[0].reasons.empty());
  EXPECT_NE(gate.scenes[0].reasons[0].find("the base revision's image is broken"),
            std::string::npos)
      << gate.scenes[0].reasons[0];
}

// An image that failed without metrics (unreadable) says why, and fails the change.
TEST(GateVerdict, AnUnreadableImageFailsWithItsReason) {
  SceneResult scene = compared("gears", 0.0, -0.01, 0.01);
  scene.images = {{Role::head,
                   ImageReference::base,
                   "a.ppm",
                   "b.ppm",
                   ImageVerdict::fail,
                   "a.ppm: cannot read image: bad",
                   {},
                   {},
                   std::nullopt}};
  const GateResult gate = evaluate_gate(compare_document({scene}), GatePolicy{});
  EXPECT_EQ(gate.exit_code, 1);
  ASSERT_EQ(gate.scenes[0].reasons.size(), 1u);
  EXPECT_EQ(gate.scenes[0].reasons[0], "image head vs base: a.ppm: cannot read image: bad");
}

TEST(GateVerdict, ARunIsJudgedOnFailuresAndImagesOnly) {
  ResultsDocument document;
  document.kind = DocumentKind::run;
  document.complete = true;
  SceneResult scene;
  scene.entry.id = "tetra";
  scene.status = SceneStatus::measured;
  document.scenes.push_back(scene);
  const GateResult gate = evaluate_gate(document, GatePolicy{});
  EXPECT_EQ(gate.scenes[0].speed, SpeedVerdict::measured);
  EXPECT_EQ(gate.exit_code, 0);
}

}  // namespace
}  // namespace raygate

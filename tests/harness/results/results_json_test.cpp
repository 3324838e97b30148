// The results document's JSON form: a full document (rounds, a failure, image checks with an
// infinite PSNR, ratios, a change, scores) survives to_json -> results_from_json field by field;
// newer or broken documents are UsageErrors naming the file; write_results replaces atomically.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "core/error.h"
#include "core/fs.h"
#include "results/results.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using ::testing::HasSubstr;

RunRecord make_run(double seconds, const std::string& dir) {
  RunRecord run;
  run.ok = true;
  run.outcome = "exited with status 0";
  run.seconds = seconds;
  run.wall_seconds = seconds + 0.25;
  run.user_seconds = seconds * 0.75;
  run.system_seconds = 0.125;
  run.max_rss_kib = 123456;
  run.image = dir + "/image.png";
  run.log = dir + "/log.txt";
  return run;
}

RatioSummary make_ratio(double ratio) {
  RatioSummary r;
  r.rounds = 3;
  r.ratio = ratio;
  r.ratio_interval = {ratio * 0.97, ratio * 1.04};
  r.relative_half_width = 0.035;
  r.log_ratio_median = std::log(ratio);
  r.log_ratio_mad_scaled = 0.0125;
  r.tracer_median_seconds = 0.75;
  r.baseline_median_seconds = 1.5;
  return r;
}

ImageMetrics make_metrics(bool identical) {
  ImageMetrics m;
  m.width = m.expected_width = 64;
  m.height = m.expected_height = 48;
  if (identical) {
    m.psnr_db = std::numeric_limits<double>::infinity();
    return m;
  }
  m.mean_error = 0.002;
  m.rms_error = 0.01;
  m.psnr_db = 41.5;
  m.max_error = 0.25;
  m.max_x = 12;
  m.max_y = 40;
  m.max_channel = 1;
  m.max_actual_value = 0.75;
  m.max_expected_value = 0.5;
  m.pixels_over_warn = 9;
  m.pixels_over_fail = 7;
  m.percent_over_fail = 0.228;
  m.mean_luminance_actual = 0.4;
  m.mean_luminance_expected = 0.375;
  m.nonfinite_values = 2;
  return m;
}

// A measured scene with a warm-up, two rounds and a golden check that passed identically.
SceneResult measured_scene() {
  SceneResult s;
  s.entry = SuiteScene{"balls", "balls", 2, 64, 48};
  s.scene_sha256 = std::string(64, 'a');
  s.status = SceneStatus::measured;
  s.runs.warmup["baseline"] = {make_run(1.5, "/w/b/warmup-1")};
  s.runs.warmup["tracer"] = {make_run(0.75, "/w/t/warmup-1")};
  for (int i = 0; i < 2; ++i) {
    Round round;
    round.order = i == 0 ? std::vector<std::string>{"baseline", "tracer"}
                         : std::vector<std::string>{"tracer", "baseline"};
    round.runs["baseline"] = make_run(1.5 + i, "/w/b/round-00" + std::to_string(i + 1));
    round.runs["tracer"] = make_run(0.75 + i, "/w/t/round-00" + std::to_string(i + 1));
    s.runs.rounds.push_back(round);
  }
  s.runs.rounds[1].runs["tracer"].reported_seconds = 1.625;
  s.runs.stop_reason = "stop_converged";
  s.runs.seconds_spent = 9.5;
  s.ratios[Role::tracer] = make_ratio(0.5);
  s.images.push_back(ImageCheck{Role::tracer,
                                ImageReference::golden,
                                "/w/t/warmup-1/image.png",
                                "/g/balls.png",
                                ImageVerdict::pass,
                                "",
                                make_metrics(true),
                                {},
                                std::nullopt});
  return s;
}

// A scene that failed in round 2, kept its first round, and whose image failed with evidence.
SceneResult failed_scene() {
  SceneResult s = measured_scene();
  s.entry.id = "tetra-small";
  s.entry.scene = "tetra";
  s.status = SceneStatus::failed;
  s.runs.rounds.resize(1);
  s.runs.stop_reason = "failed";
  s.runs.failed_role = Role::tracer;
  RunRecord crash = make_run(0.0, "/w/t/round-002");
  crash.ok = false;
  crash.outcome = "killed by signal 6 (ABRT)";
  crash.failure = "/b/tracer killed by signal 6 (ABRT)";
  s.runs.failed_run = crash;
  s.images[0].verdict = ImageVerdict::fail;
  s.images[0].metrics = make_metrics(false);
  s.images[0].evidence = {"/e/tetra.actual.png", "/e/tetra.expected.png", "/e/tetra.diff.png"};
  s.images.push_back(ImageCheck{Role::tracer,
                                ImageReference::golden,
                                "/h.png",
                                "/g/tetra-small.png",
                                ImageVerdict::error,
                                "cannot read /h.png",
                                std::nullopt,
                                {},
                                std::nullopt});
  return s;
}

// A compare scene: three roles and the change of head against base, head's image read
// against base's.
SceneResult compared_scene() {
  SceneResult s = measured_scene();
  s.entry.id = "gears";
  const auto as_compare = [](std::map<std::string, RunRecord>& runs) {
    runs["base"] = runs.at("tracer");
    runs["head"] = runs.at("tracer");
    runs.erase("tracer");
  };
  for (Round& round : s.runs.rounds) {
    as_compare(round.runs);
    round.order = {"baseline", "base", "head"};
  }
  s.runs.warmup["base"] = s.runs.warmup.at("tracer");
  s.runs.warmup.erase("tracer");
  s.ratios.clear();
  s.images = {ImageCheck{Role::head,
                         ImageReference::base,
                         "/h.png",
                         "/b.png",
                         ImageVerdict::error,
                         "cannot read /h.png",
                         std::nullopt,
                         {},
                         std::nullopt}};
  ChangeSummary c;
  c.rounds = 2;
  c.change = 0.0625;
  c.change_interval = {0.03125, 0.09375};
  c.confidence = 0.996;  // a confidence sequence with its equivalence and one-look intervals
  c.interval_kind = ChangeIntervalKind::confidence_sequence;
  c.equivalence_interval = {0.046875, 0.078125};
  c.equivalence_confidence = 0.9;
  c.one_look_interval = {0.0546875, 0.0703125};
  c.one_look_confidence = 0.95;
  c.log_change_median = 0.06;
  c.log_change_mad_scaled = 0.01;
  c.base = make_ratio(0.5);
  c.head = make_ratio(0.53125);
  s.ratios[Role::base] = c.base;
  s.ratios[Role::head] = c.head;
  c.mann_whitney = {3.0, 1.5, 0.125};
  s.change = c;
  s.change_verdict = ChangeVerdict::regressed;
  return s;
}

BuildRecord make_build() {
  BuildRecord b;
  b.sha = std::string(40, 'c');
  b.adapter_name = "make-nff";
  b.adapter_hash = std::string(64, 'd');
  b.compiler = "g++ (Debian 12.2.0-14) 12.2.0";
  b.key = "ccccccc-ddddddd-eeee";
  b.build_dir = "/cache/builds/x";
  b.src_dir = "/cache/worktrees/y";
  b.steps.push_back({{"make", "-C", "/src"}, "exited with status 0", true, 1.5, 1.25, "/l/1.log"});
  b.total_seconds = 1.5;
  b.success = true;
  return b;
}

ResultsDocument full_document() {
  ResultsDocument d;
  d.kind = DocumentKind::run;
  d.raygate_version = "0.1.0";
  d.started_at = "2024-01-02T03:04:05Z";
  d.finished_at = "2024-01-02T03:14:05Z";
  d.complete = true;
  d.machine = {{"cpu_model", "Test CPU"}, {"cores", 2}, {"load", {0.5, 0.25, 0.125}}};
  d.baseline = {"raygate-baseline 0.1.0", std::string(64, 'b'), "none", "center", "in-process"};
  d.suite = "ci";
  d.shard = "1/2";
  d.settings.schedule = ScheduleKind::alternate;
  d.settings.min_rounds = 3;
  d.settings.pin_cpus = std::vector<int>{};
  RevisionRecord r;
  r.role = Role::tracer;
  r.repository = "/repos/tracer";
  // The base Revision's fields first, then the folder: brace elision had shifted them by one
  // (the path in `revision`, the author in `commit_time`) until commit times were checked.
  r.worktree = {{"v1", "refs/tags/v1", std::string(40, 'c'), "ccccccc", "first", "Ada Tester",
                 "2023-11-14T22:14:20+00:00"},
                "/cache/worktrees/y",
                false};
  r.adapter_name = "make-nff";
  r.adapter_hash = std::string(64, 'd');
  r.adapter_file = "/adapters/make-nff.json";
  r.build = make_build();
  d.revisions.push_back(r);
  d.scenes = {measured_scene(), failed_scene()};
  d.scores[Role::tracer] = SuiteScore{2, 0.5, {0.48, 0.52}};
  return d;
}

// The run document as a compare of two revisions: base and head where it had the tracer, and a
// third scene with the change of head against base.
ResultsDocument compare_document() {
  ResultsDocument d = full_document();
  d.kind = DocumentKind::compare;
  d.revisions.push_back(d.revisions[0]);
  d.revisions[0].role = Role::base;
  d.revisions[1].role = Role::head;
  d.scenes = {compared_scene()};
  d.scores.clear();
  d.scores[Role::base] = SuiteScore{1, 0.5, {0.48, 0.52}};
  d.scores[Role::head] = SuiteScore{1, 0.53125, {0.5, 0.56}};
  return d;
}

// --- field-by-field comparison -----------------------------------------------------------------

void expect_same(const Interval& a, const Interval& b) {
  EXPECT_DOUBLE_EQ(a.lower, b.lower);
  EXPECT_DOUBLE_EQ(a.upper, b.upper);
}

void expect_same(const RatioSummary& a, const RatioSummary& b) {
  EXPECT_EQ(a.rounds, b.rounds);
  EXPECT_DOUBLE_EQ(a.ratio, b.ratio);
  expect_same(a.ratio_interval, b.ratio_interval);
  EXPECT_DOUBLE_EQ(a.relative_half_width, b.relative_half_width);
  EXPECT_DOUBLE_EQ(a.log_ratio_median, b.log_ratio_median);
  EXPECT_DOUBLE_EQ(a.log_ratio_mad_scaled, b.log_ratio_mad_scaled);
  EXPECT_DOUBLE_EQ(a.tracer_median_seconds, b.tracer_median_seconds);
  EXPECT_DOUBLE_EQ(a.baseline_median_seconds, b.baseline_median_seconds);
}

void expect_same(const ImageMetrics& a, const ImageMetrics& b) {
  EXPECT_EQ(a.size_mismatch, b.size_mismatch);
  EXPECT_EQ(a.width, b.width);
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.expected_width, b.expected_width);
  EXPECT_EQ(a.expected_height, b.expected_height);
  EXPECT_DOUBLE_EQ(a.mean_error, b.mean_error);
  EXPECT_DOUBLE_EQ(a.rms_error, b.rms_error);
  EXPECT_EQ(a.psnr_db, b.psnr_db);  // also infinity == infinity
  EXPECT_DOUBLE_EQ(a.max_error, b.max_error);
  EXPECT_EQ(a.max_x, b.max_x);
  EXPECT_EQ(a.max_y, b.max_y);
  EXPECT_EQ(a.max_channel, b.max_channel);
  EXPECT_DOUBLE_EQ(a.max_actual_value, b.max_actual_value);
  EXPECT_DOUBLE_EQ(a.max_expected_value, b.max_expected_value);
  EXPECT_EQ(a.pixels_over_warn, b.pixels_over_warn);
  EXPECT_EQ(a.pixels_over_fail, b.pixels_over_fail);
  EXPECT_DOUBLE_EQ(a.percent_over_fail, b.percent_over_fail);
  EXPECT_DOUBLE_EQ(a.mean_luminance_actual, b.mean_luminance_actual);
  EXPECT_DOUBLE_EQ(a.mean_luminance_expected, b.mean_luminance_expected);
  EXPECT_EQ(a.nonfinite_values, b.nonfinite_values);
}

void expect_same(const ImageCheck& a, const ImageCheck& b) {
  EXPECT_EQ(a.role, b.role);
  EXPECT_EQ(a.reference, b.reference);
  EXPECT_EQ(a.actual, b.actual);
  EXPECT_EQ(a.expected, b.expected);
  EXPECT_EQ(a.verdict, b.verdict);
  EXPECT_EQ(a.error, b.error);
  EXPECT_EQ(a.evidence, b.evidence);
  ASSERT_EQ(a.metrics.has_value(), b.metrics.has_value());
  if (a.metrics) expect_same(*a.metrics, *b.metrics);
}

void expect_same(const ChangeSummary& a, const ChangeSummary& b) {
  EXPECT_EQ(a.rounds, b.rounds);
  EXPECT_DOUBLE_EQ(a.change, b.change);
  expect_same(a.change_interval, b.change_interval);
  EXPECT_DOUBLE_EQ(a.confidence, b.confidence);
  EXPECT_EQ(a.interval_kind, b.interval_kind);
  expect_same(a.equivalence_interval, b.equivalence_interval);
  EXPECT_DOUBLE_EQ(a.equivalence_confidence, b.equivalence_confidence);
  expect_same(a.one_look_interval, b.one_look_interval);
  EXPECT_DOUBLE_EQ(a.one_look_confidence, b.one_look_confidence);
  EXPECT_DOUBLE_EQ(a.log_change_median, b.log_change_median);
  EXPECT_DOUBLE_EQ(a.log_change_mad_scaled, b.log_change_mad_scaled);
  expect_same(a.base, b.base);
  expect_same(a.head, b.head);
  EXPECT_DOUBLE_EQ(a.mann_whitney.u, b.mann_whitney.u);
  EXPECT_DOUBLE_EQ(a.mann_whitney.z, b.mann_whitney.z);
  EXPECT_DOUBLE_EQ(a.mann_whitney.p_value, b.mann_whitney.p_value);
}

void expect_same(const SceneRuns& a, const SceneRuns& b) {
  EXPECT_EQ(a.warmup, b.warmup);
  ASSERT_EQ(a.rounds.size(), b.rounds.size());
  for (std::size_t i = 0; i < a.rounds.size(); ++i) {
    EXPECT_EQ(a.rounds[i].order, b.rounds[i].order);
    EXPECT_EQ(a.rounds[i].runs, b.rounds[i].runs);
  }
  EXPECT_EQ(a.stop_reason, b.stop_reason);
  EXPECT_DOUBLE_EQ(a.seconds_spent, b.seconds_spent);
  EXPECT_EQ(a.failed_role, b.failed_role);
  EXPECT_EQ(a.failed_run, b.failed_run);
}

void expect_same(const SceneResult& a, const SceneResult& b) {
  SCOPED_TRACE("scene " + a.entry.id);
  EXPECT_EQ(a.entry.id, b.entry.id);
  EXPECT_EQ(a.entry.scene, b.entry.scene);
  EXPECT_EQ(a.entry.size, b.entry.size);
  EXPECT_EQ(a.entry.width, b.entry.width);
  EXPECT_EQ(a.entry.height, b.entry.height);
  EXPECT_EQ(a.scene_sha256, b.scene_sha256);
  EXPECT_EQ(a.status, b.status);
  expect_same(a.runs, b.runs);
  ASSERT_EQ(a.ratios.size(), b.ratios.size());
  for (const auto& [role, ratio] : a.ratios) expect_same(ratio, b.ratios.at(role));
  ASSERT_EQ(a.change.has_value(), b.change.has_value());
  if (a.change) expect_same(*a.change, *b.change);
  EXPECT_EQ(a.change_verdict, b.change_verdict);
  ASSERT_EQ(a.images.size(), b.images.size());
  for (std::size_t i = 0; i < a.images.size(); ++i) expect_same(a.images[i], b.images[i]);
}

void expect_same(const RevisionRecord& a, const RevisionRecord& b) {
  EXPECT_EQ(a.role, b.role);
  EXPECT_EQ(a.repository, b.repository);
  EXPECT_EQ(a.worktree, b.worktree);
  EXPECT_EQ(a.adapter_name, b.adapter_name);
  EXPECT_EQ(a.adapter_hash, b.adapter_hash);
  EXPECT_EQ(a.adapter_file, b.adapter_file);
  EXPECT_EQ(a.build, b.build);
}

void expect_same(const ResultsDocument& a, const ResultsDocument& b) {
  EXPECT_EQ(a.schema_version, b.schema_version);
  EXPECT_EQ(a.kind, b.kind);
  EXPECT_EQ(a.raygate_version, b.raygate_version);
  EXPECT_EQ(a.started_at, b.started_at);
  EXPECT_EQ(a.finished_at, b.finished_at);
  EXPECT_EQ(a.complete, b.complete);
  EXPECT_EQ(a.machine, b.machine);
  EXPECT_EQ(a.baseline.version, b.baseline.version);
  EXPECT_EQ(a.baseline.source_sha256, b.baseline.source_sha256);
  EXPECT_EQ(a.baseline.accel, b.baseline.accel);
  EXPECT_EQ(a.baseline.sampling, b.baseline.sampling);
  EXPECT_EQ(a.baseline.timing, b.baseline.timing);
  EXPECT_EQ(a.suite, b.suite);
  EXPECT_EQ(a.shard, b.shard);
  EXPECT_EQ(a.settings, b.settings);
  ASSERT_EQ(a.revisions.size(), b.revisions.size());
  for (std::size_t i = 0; i < a.revisions.size(); ++i) expect_same(a.revisions[i], b.revisions[i]);
  ASSERT_EQ(a.scenes.size(), b.scenes.size());
  for (std::size_t i = 0; i < a.scenes.size(); ++i) expect_same(a.scenes[i], b.scenes[i]);
  ASSERT_EQ(a.scores.size(), b.scores.size());
  for (const auto& [role, score] : a.scores) {
    EXPECT_EQ(score.scenes, b.scores.at(role).scenes);
    EXPECT_DOUBLE_EQ(score.score, b.scores.at(role).score);
    expect_same(score.interval, b.scores.at(role).interval);
  }
}

std::string usage_error(const json& document) {
  try {
    results_from_json(document, "shard-7.json");
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no error";
}

// --- tests -------------------------------------------------------------------------------------

TEST(ResultsJson, FullDocumentSurvivesTheRoundTrip) {
  for (const ResultsDocument& original : {full_document(), compare_document()}) {
    expect_same(original, results_from_json(to_json(original), "memory"));
  }
}

TEST(ResultsJson, RoundTripThroughTextIsExact) {
  for (const ResultsDocument& original : {full_document(), compare_document()}) {
    const std::string text = to_json(original).dump(1);
    const ResultsDocument back = results_from_json(json::parse(text), "memory");
    expect_same(original, back);
    EXPECT_EQ(to_json(back).dump(1), text);
  }
}

// Each document measures the roles of its kind: head's ratios or a change in a run document, or
// the tracer's in a compare, were hand-made, and each reader picked out what it looked for.
TEST(ResultsJson, ADocumentCarriesOnlyTheRolesOfItsKind) {
  json run = to_json(full_document());
  run["scenes"][0]["ratios"]["head"] = run["scenes"][0]["ratios"]["tracer"];
  EXPECT_THAT(usage_error(run), HasSubstr("$.scenes[0].ratios.head: unknown role \"head\""));
  run = to_json(full_document());
  run["scenes"][0]["change"] = to_json(compare_document())["scenes"][0]["change"];
  EXPECT_THAT(usage_error(run), HasSubstr("$.scenes[0].change: a run document has no change"));
  json compare = to_json(compare_document());
  compare["scenes"][0]["rounds"][0]["runs"]["tracer"] =
      compare["scenes"][0]["rounds"][0]["runs"]["base"];
  EXPECT_THAT(usage_error(compare), HasSubstr("unknown role \"tracer\""));
}

TEST(ResultsJson, InfinitePsnrIsWrittenAsNullAndReadBackAsInfinity) {
  const json j = to_json(full_document());
  const json& metrics = j["scenes"][0]["images"][0]["metrics"];
  EXPECT_TRUE(metrics["psnr_db"].is_null());
  EXPECT_TRUE(std::isinf(results_from_json(j, "memory").scenes[0].images[0].metrics->psnr_db));
}

// An unbounded interval is written with null bounds and read back unbounded, not as 0 (which put
// lower above upper once written again; found by fuzzing the round trip).
TEST(ResultsJson, AnUnboundedIntervalSurvivesTheRoundTrip) {
  ResultsDocument d = full_document();
  d.scenes[0].ratios[Role::tracer].ratio_interval = {0.5, std::numeric_limits<double>::infinity()};
  d.scores[Role::tracer].interval = {-std::numeric_limits<double>::infinity(), 0.52};
  const json j = to_json(d);
  EXPECT_TRUE(j["scenes"][0]["ratios"]["tracer"]["ratio_interval"]["upper"].is_null());
  const ResultsDocument back = results_from_json(j, "memory");
  EXPECT_TRUE(std::isinf(back.scenes[0].ratios.at(Role::tracer).ratio_interval.upper));
  EXPECT_LT(back.scores.at(Role::tracer).interval.lower, 0.0);
  EXPECT_EQ(to_json(back).dump(), j.dump());
}

TEST(ResultsJson, FailureIsStoredWithItsRoleAndRun) {
  const json j = to_json(full_document());
  const json& failure = j["scenes"][1]["failure"];
  EXPECT_EQ(failure["role"], "tracer");
  EXPECT_EQ(failure["run"]["outcome"], "killed by signal 6 (ABRT)");
  EXPECT_EQ(failure["run"]["log"], "/w/t/round-002/log.txt");
  EXPECT_TRUE(j["scenes"][0]["failure"].is_null());
}

TEST(ResultsJson, ChangeIntervalKindIsCheckedAndDefaultsForOldDocuments) {
  json j = to_json(compare_document());
  json& change = j["scenes"][0]["change"];
  EXPECT_EQ(change["interval_kind"], "confidence-sequence");
  change["interval_kind"] = "bootstrap";
  const std::string message = usage_error(j);
  EXPECT_NE(message.find("shard-7.json"), std::string::npos) << message;
  EXPECT_NE(message.find("$.scenes[0].change.interval_kind: unknown value \"bootstrap\""),
            std::string::npos)
      << message;
  // A document from before the sequences: no kind, no extra intervals, the one-look rule.
  for (const char* key : {"interval_kind", "equivalence_interval", "equivalence_confidence",
                          "one_look_interval", "one_look_confidence"}) {
    change.erase(key);
  }
  const ResultsDocument old = results_from_json(j, "old.json");
  EXPECT_EQ(old.scenes[0].change->interval_kind, ChangeIntervalKind::order_statistic);
}

// The tenth sweep: a null change beside its interval read as +0% (INCONCLUSIVE where the interval
// said REGRESSED), and a change of 0 rounds, or of more rounds than listed, as any other.
TEST(ResultsJson, AChangeAgreesWithItsIntervalAndRounds) {
  json j = to_json(compare_document());
  j["scenes"][0]["change"]["change"] = nullptr;
  EXPECT_THAT(usage_error(j),
              HasSubstr("$.scenes[0].change.change: is null, but its change_interval is not"));
  j = to_json(compare_document());
  j["scenes"][0]["change"]["rounds"] = 0;
  EXPECT_THAT(usage_error(j), HasSubstr("$.scenes[0].change.rounds: 0 rounds, but a change"));
  // The eleventh sweep: 50 beside the 2 listed made the gate's sequence decide.
  j = to_json(compare_document());
  j["scenes"][0]["change"]["rounds"] = 50;
  EXPECT_THAT(usage_error(j), HasSubstr("50 rounds, but the scene lists 2"));
}

TEST(ResultsJson, AnUnknownImageVerdictIsAUsageErrorNamingTheField) {
  json j = to_json(full_document());
  EXPECT_EQ(j["scenes"][1]["images"][0]["verdict"], "fail");
  j["scenes"][1]["images"][0]["verdict"] = "failed";
  const std::string message = usage_error(j);
  EXPECT_NE(message.find("shard-7.json"), std::string::npos) << message;
  EXPECT_NE(message.find("$.scenes[1].images[0].verdict: unknown value \"failed\""),
            std::string::npos)
      << message;
}

TEST(ResultsJson, NewerSchemaVersionAsksForAnUpgrade) {
  json j = to_json(full_document());
  j["schema_version"] = kResultsSchemaVersion + 1;
  const std::string message = usage_error(j);
  EXPECT_NE(message.find("shard-7.json"), std::string::npos) << message;
  EXPECT_NE(message.find("upgrade raygate"), std::string::npos) << message;
}

TEST(ResultsJson, MissingKeyIsAUsageErrorNamingTheFileAndKey) {
  json j = to_json(full_document());
  j["scenes"][1].erase("rounds");
  const std::string message = usage_error(j);
  EXPECT_NE(message.find("shard-7.json: $.scenes[1]: missing required key 'rounds'"),
            std::string::npos)
      << message;
}

TEST(ResultsJson, WrongTypesAndNonObjectsAreUsageErrors) {
  json j = to_json(full_document());
  j["complete"] = "yes";
  EXPECT_NE(usage_error(j).find("shard-7.json"), std::string::npos);
  EXPECT_NE(usage_error(json::array()).find("shard-7.json"), std::string::npos);
  EXPECT_NE(usage_error(json{{"schema_version", "1"}}).find("shard-7.json"), std::string::npos);
}

TEST(ResultsJson, WriteResultsReplacesTheFileAtomically) {
  TempDir dir;
  const fs::path path = dir.path() / "out" / "results.json";
  ResultsDocument first = full_document();
  first.complete = false;
  first.scenes.resize(1);
  write_results(first, path);
  EXPECT_EQ(read_results(path).scenes.size(), 1u);

  const ResultsDocument second = full_document();
  write_results(second, path);
  EXPECT_EQ(read_file(path), to_json(second).dump(1) + "\n");
  expect_same(second, read_results(path));
  // Only the document is left in its folder: no temporary file beside it.
  std::vector<fs::path> entries(fs::directory_iterator(path.parent_path()), {});
  EXPECT_EQ(entries, std::vector<fs::path>{path});
}

TEST(ResultsJson, ReadResultsOfNonJsonNamesTheFile) {
  TempDir dir;
  const fs::path path = dir.path() / "results.json";
  write_file_atomically(path, "{\"schema_version\": 1,");
  try {
    read_results(path);
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string() + ":1:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(": not JSON"), std::string::npos) << e.what();
  }
}

// A document read from disk (gate, report, merge, golden bless) is untrusted: a key given twice
// would let its last copy win silently, and 1e400 was an internal error. Both are usage errors
// naming the file, line, column and JSON path.
TEST(ResultsJson, ReadResultsRefusesDuplicateKeysAndOutOfRangeNumbersWhereTheyAre) {
  TempDir dir;
  const fs::path path = dir.path() / "results.json";
  write_results(full_document(), path);
  const std::string text = read_file(path);
  const auto error_of = [&](const std::string& changed) {
    write_file_atomically(path, changed);
    try {
      read_results(path);
    } catch (const UsageError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // The same key twice at the top: "complete": false after "complete": true.
  std::string twice = text;
  twice.insert(twice.find("\"complete\""), "\"complete\": false,\n ");
  const std::string duplicate = error_of(twice);
  EXPECT_NE(duplicate.find(path.string() + ":"), std::string::npos) << duplicate;
  EXPECT_NE(duplicate.find(": $: duplicate key 'complete'"), std::string::npos) << duplicate;
  // A machine's core count past a double's range.
  std::string huge = text;
  const std::size_t cores = huge.find("\"cores\": ");
  ASSERT_NE(cores, std::string::npos);
  huge.replace(cores, std::string("\"cores\": ").size(), "\"cores\": 1e400, \"x\": ");
  const std::string range = error_of(huge);
  EXPECT_NE(range.find(": $.machine.cores: number 1e400 is out of range"), std::string::npos)
      << range;
}

}  // namespace
}  // namespace raygate

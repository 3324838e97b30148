// `raygate merge` as a library: shards of one suite merged equal the single job that measured
// every scene (scenes in suite order, suite score, gate verdict), whatever order the files come
// in; every kind of inconsistency is refused naming both files and the field; a missing shard is
// refused unless allowed (then incomplete, gate exit 3); machines of all shards are kept; the
// merged document survives the JSON reader.
#include <gtest/gtest.h>

#include <functional>

#include "core/error.h"
#include "core/fs.h"
#include "gate/verdict.h"
#include "results_fixture.h"
#include "results/merge.h"
#include "results/scores.h"
#include "results/shard.h"

namespace raygate {
namespace {

using nlohmann::json;

const std::vector<test::SceneSpec> kScenes{{.id = "balls", .ratio = 1.2, .baseline_seconds = 1.2},
                                           {.id = "gears", .ratio = 0.8, .baseline_seconds = 1.0},
                                           {.id = "mount",
                                            .ratio = 1.5,
                                            .baseline_seconds = 0.9,
                                            .max_error = 0.5,
                                            .verdict = ImageVerdict::fail},
                                           {.id = "rings", .ratio = 0.9, .baseline_seconds = 0.5},
                                           {.id = "teapot", .ratio = 1.1, .baseline_seconds = 0.6}};

std::vector<std::string> ids_of(const std::vector<test::SceneSpec>& scenes) {
  std::vector<std::string> ids;
  for (const test::SceneSpec& s : scenes) ids.push_back(s.id);
  return ids;
}

test::DocumentSpec spec_with(const std::vector<test::SceneSpec>& scenes) {
  test::DocumentSpec spec;
  spec.sha = test::fake_sha(7);
  spec.scenes = scenes;
  return spec;
}

// What one job measuring every scene writes: its scores from its rounds.
ResultsDocument single_job() {
  ResultsDocument d = test::make_document(spec_with(kScenes));
  d.scores = suite_scores(d.scenes, scored_roles(d));
  return d;
}

// Shard `index` of `count` of kScenes, split as `raygate run --shard` does, on its own runner.
ResultsDocument shard_document(int index, int count) {
  std::vector<SuiteScene> suite;
  for (const test::SceneSpec& s : kScenes) suite.push_back({s.id, s.id, 1, 64, 64});
  const std::vector<SuiteScene> mine = shard_scenes(suite, {index, count}, {});
  std::vector<test::SceneSpec> scenes;
  for (const test::SceneSpec& s : kScenes) {
    for (const SuiteScene& m : mine) {
      if (m.id == s.id) scenes.push_back(s);
    }
  }
  test::DocumentSpec spec = spec_with(scenes);
  spec.hostname = "ci-runner-" + std::to_string(index);
  spec.started_at = "2026-01-02T00:0" + std::to_string(index) + ":00Z";
  ResultsDocument d = test::make_document(spec);
  d.shard = to_string(ShardSpec{index, count});
  d.settings.shard = ShardRecord{{index, count}, ids_of(kScenes), "equal", std::string(64, 'a')};
  d.settings.golden_dir = "/runner-" + std::to_string(index) + "/golden";  // per runner
  d.scores = suite_scores(d.scenes, scored_roles(d));
  return d;
}

std::vector<MergeInput> two_shards() {
  return {{"a.json", shard_document(1, 2)}, {"b.json", shard_document(2, 2)}};
}

std::string merge_error(const std::vector<MergeInput>& inputs, MergeOptions options = {}) {
  try {
    merge_shards(inputs, options);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Merge, EqualsTheSingleJobThatMeasuredEveryScene) {
  const ResultsDocument whole = single_job();
  for (const bool reversed : {false, true}) {
    std::vector<MergeInput> inputs = two_shards();
    if (reversed) std::swap(inputs[0], inputs[1]);
    const MergeResult merged = merge_shards(inputs, {});
    const ResultsDocument& d = merged.document;
    EXPECT_TRUE(merged.warnings.empty());
    EXPECT_TRUE(d.complete);
    EXPECT_TRUE(d.shard.empty());
    EXPECT_FALSE(d.settings.shard.has_value());
    ASSERT_EQ(d.scenes.size(), whole.scenes.size());
    for (std::size_t i = 0; i < d.scenes.size(); ++i) {
      EXPECT_EQ(d.scenes[i].entry.id, whole.scenes[i].entry.id) << "suite order";
    }
    const SuiteScore& score = d.scores.at(Role::tracer);
    const SuiteScore& expected = whole.scores.at(Role::tracer);
    EXPECT_EQ(score.scenes, expected.scenes);
    EXPECT_DOUBLE_EQ(score.score, expected.score);
    EXPECT_DOUBLE_EQ(score.interval.lower, expected.interval.lower);
    EXPECT_DOUBLE_EQ(score.interval.upper, expected.interval.upper);
    // Neither shard alone has the suite's score.
    EXPECT_NE(inputs[0].document.scores.at(Role::tracer).score, expected.score);

    const GateResult gate = evaluate_gate(d, GatePolicy{});
    const GateResult expected_gate = evaluate_gate(whole, GatePolicy{});
    EXPECT_EQ(gate.exit_code, expected_gate.exit_code);
    EXPECT_EQ(gate.exit_code, 1);  // mount's image fails
    ASSERT_EQ(gate.scenes.size(), expected_gate.scenes.size());
    for (std::size_t i = 0; i < gate.scenes.size(); ++i) {
      EXPECT_EQ(gate.scenes[i].id, expected_gate.scenes[i].id);
      EXPECT_EQ(gate.scenes[i].outcome, expected_gate.scenes[i].outcome);
    }
  }
}

TEST(Merge, KeepsEveryShardsMachineAndSpansTheirTimes) {
  const ResultsDocument d = merge_shards(two_shards(), {}).document;
  EXPECT_EQ(d.machine.at("hostname"), "ci-runner-1");  // shard 1's
  ASSERT_TRUE(d.settings.merged_shards.has_value());
  const std::vector<MergedShard>& shards = *d.settings.merged_shards;
  ASSERT_EQ(shards.size(), 2u);
  EXPECT_EQ(shards[0].spec.index, 1);
  EXPECT_EQ(shards[0].document, "a.json");
  EXPECT_EQ(shards[0].machine.at("hostname"), "ci-runner-1");
  EXPECT_EQ(shards[1].machine.at("hostname"), "ci-runner-2");
  EXPECT_EQ(shards[1].scenes, (std::vector<std::string>{"gears", "rings"}));
  EXPECT_EQ(d.started_at, "2026-01-02T00:01:00Z");
  EXPECT_EQ(d.finished_at, "2026-01-02T00:02:00Z");
}

TEST(Merge, RoundTripsThroughTheJsonReader) {
  const ResultsDocument d = merge_shards(two_shards(), {}).document;
  const TempDir dir;
  write_results(d, dir.path() / "merged.json");
  const ResultsDocument back = read_results(dir.path() / "merged.json");
  EXPECT_EQ(to_json(back), to_json(d));
  EXPECT_EQ(back.scenes.size(), 5u);
  EXPECT_EQ(back.scores.at(Role::tracer).scenes, 5u);
}

struct Inconsistency {
  std::string name;
  std::string field;  // what the message must name
  std::function<void(ResultsDocument&)> change;
};

TEST(Merge, RefusesInconsistentShardsNamingBothFilesAndTheField) {
  const std::vector<Inconsistency> cases{
      {"kind", "kind", [](ResultsDocument& d) { d.kind = DocumentKind::compare; }},
      {"commit", "revisions[tracer].worktree.sha",
       [](ResultsDocument& d) { d.revisions[0].worktree.sha = test::fake_sha(8); }},
      {"dirty", "revisions[tracer].worktree.dirty",
       [](ResultsDocument& d) { d.revisions[0].worktree.dirty = true; }},
      {"adapter", "revisions[tracer].adapter.hash",
       [](ResultsDocument& d) { d.revisions[0].adapter_hash = std::string(64, 'c'); }},
      {"roles", "revisions (roles)", [](ResultsDocument& d) { d.revisions[0].role = Role::head; }},
      {"baseline version", "baseline.version",
       [](ResultsDocument& d) { d.baseline.version = "raygate-baseline 0.2.0"; }},
      {"baseline sha", "baseline.source_sha256",
       [](ResultsDocument& d) { d.baseline.source_sha256 = std::string(64, 'd'); }},
      {"suite", "suite", [](ResultsDocument& d) { d.suite = "full"; }},
      {"schema", "schema_version", [](ResultsDocument& d) { d.schema_version = 0; }},
      {"shard count", "shard count", [](ResultsDocument& d) { d.settings.shard->spec.count = 3; }},
      {"selection", "settings.shard.suite_scenes",
       [](ResultsDocument& d) {
         d.settings.shard->suite_scenes = {"balls", "gears"};
       }},
      // Sweep 13: a shard of another suite file named ci (balls at another size) merged.
      {"suite contents", "settings.shard.suite_sha256",
       [](ResultsDocument& d) { d.settings.shard->suite_sha256 = std::string(64, 'e'); }},
      {"settings", "settings.target",
       [](ResultsDocument& d) { d.settings.unknown["target"] = 0.05; }},
      {"typed settings", "settings.max_rounds",
       [](ResultsDocument& d) { d.settings.max_rounds = 7; }},
  };
  for (const Inconsistency& c : cases) {
    std::vector<MergeInput> inputs = two_shards();
    c.change(inputs[1].document);
    const std::string message = merge_error(inputs);
    EXPECT_NE(message.find("a.json and b.json"), std::string::npos) << c.name << ": " << message;
    EXPECT_NE(message.find(c.field), std::string::npos) << c.name << ": " << message;
  }
}

TEST(Merge, RefusesOverlappingAndRepeatedShards) {
  std::vector<MergeInput> overlap = two_shards();
  overlap[1].document.scenes.push_back(overlap[0].document.scenes.front());
  EXPECT_NE(merge_error(overlap).find("scene 'balls' is in both a.json and b.json"),
            std::string::npos)
      << merge_error(overlap);

  const std::vector<MergeInput> twice{{"a.json", shard_document(1, 2)},
                                      {"c.json", shard_document(1, 2)}};
  EXPECT_NE(merge_error(twice).find("a.json and c.json are both shard 1/2"), std::string::npos)
      << merge_error(twice);

  std::vector<MergeInput> stranger = two_shards();
  stranger[1].document.scenes.front().entry.id = "tree";
  EXPECT_NE(merge_error(stranger).find("b.json has scene 'tree'"), std::string::npos)
      << merge_error(stranger);
}

// A sweep: the two shards' documents with their indexes swapped (label and settings.shard.index
// both) merged silently. With equal costs the split is known, so a scene in the wrong shard is
// refused, naming the shard the split gave it.
TEST(Merge, ShardIndexesSwappedByHandAreRefused) {
  std::vector<MergeInput> swapped = two_shards();
  for (MergeInput& input : swapped) {
    ShardRecord& record = *input.document.settings.shard;
    record.spec.index = 3 - record.spec.index;
    input.document.shard = to_string(record.spec);
  }
  const std::string message = merge_error(swapped);
  EXPECT_NE(message.find("merge: b.json: scene 'gears' belongs to shard 2/2 of the split, not to "
                         "1/2 (settings.shard.index edited?)"),
            std::string::npos)
      << message;
  // Split by another document's times, the costs are not recorded: merged as before.
  std::vector<MergeInput> by_times = two_shards();
  for (MergeInput& input : by_times) input.document.settings.shard->cost_basis = "sha256:ab";
  EXPECT_EQ(merge_error(by_times), "no error");
}

TEST(Merge, MissingShardIsRefusedUnlessPartialIsAllowed) {
  const std::vector<MergeInput> one{{"a.json", shard_document(1, 3)},
                                    {"c.json", shard_document(3, 3)}};
  const std::string message = merge_error(one);
  EXPECT_NE(message.find("shard 2/3 missing"), std::string::npos) << message;
  EXPECT_NE(message.find("--allow-partial"), std::string::npos) << message;

  MergeOptions partial;
  partial.allow_partial = true;
  const MergeResult merged = merge_shards(one, partial);
  EXPECT_FALSE(merged.document.complete);
  ASSERT_FALSE(merged.warnings.empty());
  EXPECT_NE(merged.warnings.front().find("2/3"), std::string::npos);
  EXPECT_EQ(evaluate_gate(merged.document, GatePolicy{}).exit_code, 1);  // mount still fails
}

TEST(Merge, IncompleteShardGivesAnIncompleteDocumentThatCannotPass) {
  std::vector<MergeInput> inputs = two_shards();
  inputs[0].document.complete = false;
  inputs[0].document.scenes.erase(inputs[0].document.scenes.begin() + 1);  // mount: killed
  const MergeResult merged = merge_shards(inputs, {});
  EXPECT_FALSE(merged.document.complete);
  ASSERT_EQ(merged.warnings.size(), 1u);
  EXPECT_NE(merged.warnings.front().find("mount"), std::string::npos) << merged.warnings.front();
  EXPECT_EQ(evaluate_gate(merged.document, GatePolicy{}).exit_code, 3);
}

TEST(Merge, RefusesADocumentThatIsNoShard) {
  std::vector<MergeInput> inputs = two_shards();
  inputs[1].document.settings.shard.reset();
  inputs[1].document.shard.clear();
  EXPECT_NE(merge_error(inputs).find("b.json records no shard"), std::string::npos)
      << merge_error(inputs);
  EXPECT_NE(merge_error({}).find("no documents"), std::string::npos);
}

}  // namespace
}  // namespace raygate

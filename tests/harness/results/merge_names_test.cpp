// `raygate merge` refuses shards whose names could become paths outside their folder (scene ids,
// suite, adapter names) and a top-level shard label that disagrees with settings.shard: the
// merged document feeds golden bless --from-run and reports, which build paths from them.
#include <gtest/gtest.h>

#include <functional>

#include "core/error.h"
#include "results_fixture.h"
#include "results/merge.h"
#include "results/shard.h"

namespace raygate {
namespace {

// Two matching shards of a two-scene suite; `edit` changes the first one.
std::string merge_error(const std::function<void(ResultsDocument&)>& edit) {
  std::vector<MergeInput> inputs;
  const std::vector<std::string> ids{"balls", "gears"};
  for (int index = 1; index <= 2; ++index) {
    test::DocumentSpec spec;
    spec.sha = test::fake_sha(3);
    spec.scenes = {{.id = ids[static_cast<std::size_t>(index - 1)]}};
    ResultsDocument d = test::make_document(spec);
    d.shard = to_string(ShardSpec{index, 2});
    d.settings.shard = ShardRecord{{index, 2}, ids, "equal", {}};
    inputs.push_back({index == 1 ? "a.json" : "b.json", d});
  }
  edit(inputs[0].document);
  try {
    merge_shards(inputs, {});
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MergeNames, UnchangedShardsMerge) {
  EXPECT_EQ(merge_error([](ResultsDocument&) {}), "no error");
}

TEST(MergeNames, NamesThatWouldEscapeAFolderAreRefusedNamingTheField) {
  EXPECT_NE(merge_error([](ResultsDocument& d) {
              d.scenes[0].entry.id = "../../x";
            }).find("merge: a.json: scenes[0].entry.id '../../x' may hold only"),
            std::string::npos);
  EXPECT_NE(merge_error([](ResultsDocument& d) {
              d.suite = "/tmp/x";
            }).find("merge: a.json: suite '/tmp/x'"),
            std::string::npos);
  EXPECT_NE(merge_error([](ResultsDocument& d) {
              d.revisions[0].adapter_name = "../../x";
            }).find("merge: a.json: revisions[0].adapter.name '../../x'"),
            std::string::npos);
  EXPECT_NE(merge_error([](ResultsDocument& d) {
              d.settings.shard->suite_scenes[1] = "..";
            }).find("settings.shard.suite_scenes[1] '..'"),
            std::string::npos);
}

TEST(MergeNames, ShardLabelMustAgreeWithSettings) {
  EXPECT_EQ(merge_error([](ResultsDocument& d) { d.shard = "../../x"; }),
            "merge: a.json: shard '../../x' disagrees with settings.shard (1/2)");
  EXPECT_EQ(merge_error([](ResultsDocument& d) { d.shard = "2/2"; }),
            "merge: a.json: shard '2/2' disagrees with settings.shard (1/2)");
}

}  // namespace
}  // namespace raygate

// `raygate run --shard K/N` and `raygate merge` end to end on the fixture tracer's throwaway
// repository and the tiny two-scene suite: shards 1/2 and 2/2 each measure one scene and record
// the split; merged, they make one complete document of both scenes in suite order (exit 0); a
// shard of another revision is refused (exit 2); bad shard values are usage errors (exit 2).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "checkout/git_fixture.h"
#include "cli_support.h"
#include "results/results.h"
#include "results/shard.h"
#include "tracer_fixture.h"

namespace raygate::test {
namespace {

namespace fs = std::filesystem;

class ShardCli : public TracerRepoTest {
 protected:
  // raygate run of `rev` on the tiny suite, few rounds, as shard `shard`, into `out`.
  CliRun run_shard(const std::string& rev, const std::string& shard, const fs::path& out,
                   const std::string& rounds = "2") {
    return run_raygate({"run",
                        "--repo",
                        repo_.path().string(),
                        "--rev",
                        rev,
                        "--adapter",
                        "make-nff",
                        "--suite",
                        suite_.string(),
                        "--cache-dir",
                        cache_.string(),
                        "--golden-dir",
                        "no-goldens",
                        "--max-rounds",
                        rounds,
                        "--warmup",
                        "0",
                        "--shard",
                        shard,
                        "--out",
                        out.string()},
                       dir_);
  }

  CliRun merge(const std::vector<fs::path>& documents, const fs::path& out) {
    std::vector<std::string> args{"merge"};
    for (const fs::path& document : documents) args.push_back(document.string());
    args.insert(args.end(), {"-o", out.string(), "--store", (cache_ / "results.db").string()});
    return run_raygate(args, dir_);
  }
};

std::vector<std::string> scene_ids(const ResultsDocument& document) {
  std::vector<std::string> ids;
  for (const SceneResult& scene : document.scenes) ids.push_back(scene.entry.id);
  return ids;
}

TEST_F(ShardCli, TwoShardsMergeIntoOneDocumentAndAnotherRevisionIsRefused) {
  const std::string sha = commit(sources_.fast, "tracer");
  const fs::path first = dir_.path() / "shard-1.json";
  const fs::path second = dir_.path() / "shard-2.json";
  const CliRun one = run_shard(sha, "1/2", first);
  ASSERT_EQ(one.exit_code, 0) << one.out;
  EXPECT_TRUE(has(one.out, "1 scene, shard 1/2 of 2 selected scenes")) << one.out;
  const CliRun two = run_shard(sha, "2/2", second);
  ASSERT_EQ(two.exit_code, 0) << two.out;

  // Equal costs: round-robin in suite order, tetra then balls.
  const ResultsDocument a = read_results(first);
  const ResultsDocument b = read_results(second);
  EXPECT_EQ(scene_ids(a), std::vector<std::string>{"tetra"});
  EXPECT_EQ(scene_ids(b), std::vector<std::string>{"balls"});
  EXPECT_EQ(a.shard, "1/2");
  const std::optional<ShardRecord>& record = b.settings.shard;
  ASSERT_TRUE(record.has_value());
  EXPECT_EQ(record->spec.index, 2);
  EXPECT_EQ(record->spec.count, 2);
  EXPECT_EQ(record->suite_scenes, (std::vector<std::string>{"tetra", "balls"}));

  const fs::path merged_path = dir_.path() / "merged.json";
  const CliRun merged = merge({second, first}, merged_path);
  ASSERT_EQ(merged.exit_code, 0) << merged.out;
  EXPECT_TRUE(has(merged.out, "merged 2 shard documents of suite tiny: 2 scenes")) << merged.out;
  EXPECT_TRUE(has(merged.out, "stored in")) << merged.out;
  const ResultsDocument d = read_results(merged_path);
  EXPECT_TRUE(d.complete);
  EXPECT_TRUE(d.shard.empty());
  EXPECT_EQ(scene_ids(d), (std::vector<std::string>{"tetra", "balls"}));
  ASSERT_TRUE(d.scores.contains(Role::tracer));
  EXPECT_EQ(d.scores.at(Role::tracer).scenes, 2u);
  ASSERT_TRUE(d.settings.merged_shards.has_value());
  EXPECT_EQ(d.settings.merged_shards->size(), 2u);

  // Shard 2 of the next commit does not belong with shard 1 of this one.
  const std::string next = commit(sources_.slow, "trace every pixel four times");
  const fs::path other = dir_.path() / "shard-2-next.json";
  ASSERT_EQ(run_shard(next, "2/2", other, "1").exit_code, 0);
  const CliRun refused = merge({first, other}, dir_.path() / "refused.json");
  EXPECT_EQ(refused.exit_code, 2) << refused.out;
  EXPECT_TRUE(has(refused.out, first.string() + " and " + other.string())) << refused.out;
  EXPECT_TRUE(has(refused.out, "revisions[tracer].worktree.sha")) << refused.out;
  EXPECT_FALSE(has(refused.out, "gate policy")) << refused.out;  // nothing was judged
  EXPECT_FALSE(fs::exists(dir_.path() / "refused.json"));
}

TEST_F(ShardCli, BadShardValuesAreUsageErrors) {
  commit(sources_.fast, "tracer");
  for (const std::string bad : {"0/3", "4/3", "x", "3/3"}) {
    const CliRun r = run_shard("HEAD", bad, dir_.path() / "never.json");
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.out;
    EXPECT_TRUE(has(r.out, "--shard")) << r.out;
  }
  EXPECT_FALSE(fs::exists(dir_.path() / "never.json"));
}

}  // namespace
}  // namespace raygate::test

// The split of `--shard K/N`: shards are disjoint, together cover the selection, keep suite
// order, are the same on every call, and balance expected cost (longest first; equal costs are
// round-robin); bad K/N and malformed settings.shard records are UsageErrors; documents without
// settings.shard still load.
#include <fmt/core.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"
#include "results_fixture.h"
#include "results/shard.h"

namespace raygate {
namespace {

using nlohmann::json;

std::vector<SuiteScene> suite_of(int count) {
  std::vector<SuiteScene> scenes;
  for (int i = 0; i < count; ++i) scenes.push_back({fmt::format("s{}", i), "balls", 1, 64, 64});
  return scenes;
}

// The ci suite's 13 scenes with their baseline seconds from docs/scenes.md, in suite order.
const std::vector<std::pair<std::string, double>> kCiSeconds{
    {"balls", 1.178},  {"gears", 0.995}, {"mount", 0.852},    {"rings", 0.528},
    {"teapot", 0.615}, {"tetra", 0.488}, {"tree", 0.742},     {"lattice", 0.490},
    {"shells", 0.502}, {"jacks", 0.611}, {"sombrero", 0.535}, {"sample", 0.457},
    {"nurbtst", 0.622}};

std::string usage_message(const std::string& text) {
  try {
    parse_shard(text);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ShardSpec, ParsesKOfN) {
  const ShardSpec two_of_four = parse_shard("2/4");
  EXPECT_EQ(two_of_four.index, 2);
  EXPECT_EQ(two_of_four.count, 4);
  EXPECT_EQ(to_string(parse_shard("1/1")), "1/1");
  EXPECT_EQ(to_string(parse_shard("12/12")), "12/12");
}

TEST(ShardSpec, RefusesWhatIsNotAShard) {
  for (const std::string bad :
       {"0/3", "4/3", "x", "3", "1/0", "-1/3", "1/3x", " 1/3", "1/", "/3", "a/b", "1//3", ""}) {
    const std::string message = usage_message(bad);
    EXPECT_NE(message.find("--shard '" + bad + "'"), std::string::npos) << message;
    EXPECT_NE(message.find("1 <= K <= N"), std::string::npos) << message;
  }
  EXPECT_NE(usage_message("4/3").find("between 1 and 3"), std::string::npos);
}

TEST(ShardSplit, EqualCostsAreRoundRobinInSuiteOrder) {
  const std::vector<long long> costs(13, 7);
  const std::vector<int> shards = assign_shards(costs, 3);
  for (std::size_t i = 0; i < shards.size(); ++i) EXPECT_EQ(shards[i], int(i % 3) + 1) << i;
  const std::vector<SuiteScene> second = shard_scenes(suite_of(7), {2, 3}, {});
  ASSERT_EQ(second.size(), 2u);
  EXPECT_EQ(second[0].id, "s1");
  EXPECT_EQ(second[1].id, "s4");
}

TEST(ShardSplit, LongestFirstToTheLightestShard) {
  // Sorted: 5 (s0), 4 (s4), 3 (s5), then the 1s in suite order; loads go 5|0, 5|4, 5|7, 6|7,
  // 7|7, 8|7 (a tie goes to the lower shard). Round-robin would be 10|5.
  const std::vector<long long> costs{5, 1, 1, 1, 4, 3};
  EXPECT_EQ(assign_shards(costs, 2), (std::vector<int>{1, 1, 1, 1, 2, 2}));
}

// Disjoint, covering, in suite order, and the same partition on every call, for 1..7 shards of
// pseudo-random costs.
TEST(ShardSplit, ShardsAreDisjointCoveringAndDeterministic) {
  const std::vector<SuiteScene> scenes = suite_of(13);
  std::map<std::string, double> seconds;
  unsigned state = 12345;
  for (const SuiteScene& scene : scenes) {
    state = state * 1103515245u + 12345u;
    seconds[scene.id] = 0.1 + static_cast<double>((state >> 8) % 5000) / 100.0;
  }
  for (int count = 1; count <= 7; ++count) {
    std::vector<std::string> seen;
    for (int index = 1; index <= count; ++index) {
      const std::vector<SuiteScene> shard = shard_scenes(scenes, {index, count}, seconds);
      EXPECT_FALSE(shard.empty()) << index << "/" << count;
      const std::vector<SuiteScene> again = shard_scenes(scenes, {index, count}, seconds);
      ASSERT_EQ(shard.size(), again.size());
      for (std::size_t i = 0; i < shard.size(); ++i) {
        EXPECT_EQ(shard[i].id, again[i].id);
        if (i > 0) {  // suite order within a shard
          EXPECT_LT(std::stoi(shard[i - 1].id.substr(1)), std::stoi(shard[i].id.substr(1)));
        }
        seen.push_back(shard[i].id);
      }
    }
    std::sort(seen.begin(), seen.end());
    std::vector<std::string> all;
    for (const SuiteScene& scene : scenes) all.push_back(scene.id);
    std::sort(all.begin(), all.end());
    EXPECT_EQ(seen, all) << count << " shards: every scene exactly once";
  }
}

// Longest-first is within 4/3 of the best possible split; the ci suite's real costs, and a
// skewed suite where counting scenes alone would give one shard twice the work.
TEST(ShardSplit, BalancesExpectedCost) {
  std::vector<long long> ci;
  for (const auto& [id, seconds] : kCiSeconds) ci.push_back(std::llround(seconds * 1000));
  const std::vector<long long> skewed{900, 800, 700, 100, 100, 100, 100, 100, 100, 100};
  for (const std::vector<long long>& costs : {ci, skewed}) {
    const long long total = std::accumulate(costs.begin(), costs.end(), 0LL);
    const long long largest = *std::max_element(costs.begin(), costs.end());
    for (int count = 2; count <= 4; ++count) {
      std::vector<long long> load(static_cast<std::size_t>(count), 0);
      const std::vector<int> shards = assign_shards(costs, count);
      for (std::size_t i = 0; i < costs.size(); ++i) load[std::size_t(shards[i] - 1)] += costs[i];
      const auto [lightest, heaviest] = std::minmax_element(load.begin(), load.end());
      const double lower_bound = std::max(double(total) / count, double(largest));
      EXPECT_LE(double(*heaviest), lower_bound * 4.0 / 3.0) << count << " shards";
      EXPECT_LE(*heaviest - *lightest, largest) << count << " shards";
    }
  }
  // Round-robin on the skewed suite puts 900+700+100+100+100 = 1900 on shard 1 and 1200 on
  // shard 2; by cost the heavier shard carries at most 1600.
  std::vector<long long> load(2, 0);
  const std::vector<int> shards = assign_shards(skewed, 2);
  for (std::size_t i = 0; i < skewed.size(); ++i) load[std::size_t(shards[i] - 1)] += skewed[i];
  EXPECT_LE(std::max(load[0], load[1]), 1600);
}

TEST(ShardSplit, UnknownScenesCostTheMedianOfTheKnown) {
  // s0 and s1 known (10 s, 30 s: median 20 s); s2 and s3 unknown cost 20 s each.
  // Longest first: s1 (30) -> 1, s2 (20) -> 2, s3 (20) -> 2, s0 (10) -> 1: 40 | 40.
  const std::vector<SuiteScene> first = shard_scenes(suite_of(4), {1, 2}, {{"s0", 10}, {"s1", 30}});
  ASSERT_EQ(first.size(), 2u);
  EXPECT_EQ(first[0].id, "s0");
  EXPECT_EQ(first[1].id, "s1");
}

TEST(ShardSplit, MoreShardsThanScenesIsAUsageError) {
  try {
    shard_scenes(suite_of(2), {3, 3}, {});
    FAIL() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("at most 2 shards"), std::string::npos) << e.what();
  }
}

TEST(ShardSplit, ExpectedSecondsComeFromMeasuredScenes) {
  test::DocumentSpec spec;
  spec.sha = test::fake_sha(1);
  spec.scenes = {{.id = "a"}, {.id = "b", .status = SceneStatus::failed}};
  const std::map<std::string, double> seconds = expected_seconds_from(test::make_document(spec));
  ASSERT_EQ(seconds.size(), 1u);
  EXPECT_DOUBLE_EQ(seconds.at("a"), 12.5);  // the fixture's seconds_spent
}

TEST(ShardRecord, RoundTripsThroughSettingsAndOldDocumentsStillLoad) {
  test::DocumentSpec spec;
  spec.sha = test::fake_sha(1);
  spec.scenes = {{.id = "a"}};
  ResultsDocument d = test::make_document(spec);
  // Written before --shard existed: no settings.shard at all.
  const ResultsDocument old = results_from_json(to_json(d), "old.json");
  EXPECT_FALSE(old.settings.shard.has_value());
  EXPECT_TRUE(old.shard.empty());

  d.settings.shard = ShardRecord{{2, 3}, {"a", "b", "c"}, "equal", {}};
  d.shard = "2/3";
  const ResultsDocument back = results_from_json(to_json(d), "new.json");
  const std::optional<ShardRecord>& record = back.settings.shard;
  ASSERT_TRUE(record.has_value());
  EXPECT_EQ(record->spec.index, 2);
  EXPECT_EQ(record->spec.count, 3);
  EXPECT_EQ(record->suite_scenes, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(record->cost_basis, "equal");
  EXPECT_EQ(back.shard, "2/3");
}

TEST(ShardRecord, MalformedRecordIsAUsageErrorNamingTheFile) {
  test::DocumentSpec spec;
  spec.sha = test::fake_sha(1);
  json j = to_json(test::make_document(spec));
  for (const json& bad : {json{{"index", 0}, {"count", 3}}, json{{"index", 4}, {"count", 3}},
                          json{{"index", "x"}, {"count", 3}}, json{{"count", 3}}}) {
    j["settings"]["shard"] = bad;
    try {
      results_from_json(j, "shard-x.json");
      ADD_FAILURE() << "accepted " << bad.dump();
    } catch (const UsageError& e) {
      EXPECT_NE(std::string(e.what()).find("shard-x.json: $.settings.shard"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace raygate

// History from the store: one row per commit and series (the latest measurement), newest commit
// first, filters by branch, scene, role, dirtiness, repository, adapter, suite and series; one
// table per repository and adapter, trends only within a series; sparklines; time parsing.
#include <gtest/gtest.h>

#include <stdexcept>

#include "core/fs.h"
#include "results_fixture.h"
#include "store/history.h"
#include "store/store.h"
#include "store/store_rows.h"

namespace raygate::test {
namespace {

DocumentSpec commit(int seed, const std::string& day, double ratio) {
  return march_commit(seed, day, ratio);
}

// The cell of a commit line for a scene id (lines are keyed by series id).
const HistoryRow& cell(const CommitLine& line, const std::string& scene_id) {
  for (const auto& [series, row] : line.scenes) {
    if (row.scene_id == scene_id) return row;
  }
  throw std::out_of_range("no scene " + scene_id);
}

// A query with one field set (designated initializers warn under -Wextra on GCC 12).
template <typename Set>
HistoryQuery query(Set set) {
  HistoryQuery q;
  set(q);
  return q;
}

class StoreHistory : public ::testing::Test {
 protected:
  void SetUp() override { store = open_store((dir.path() / "results.db").string()); }
  void add(const DocumentSpec& spec, const std::string& branch = "main") {
    store->add(make_document(spec), branch);
  }
  TempDir dir;
  std::unique_ptr<ResultsStore> store;
};

TEST_F(StoreHistory, NewestCommitFirstWithTheLatestMeasurementOfEach) {
  add(commit(2, "12", 0.90));
  add(commit(1, "10", 1.00));
  add(commit(3, "14", 0.80));
  DocumentSpec rerun = commit(2, "12", 0.95);
  rerun.started_at = "2026-03-20T00:00:00Z";  // measured again later: supersedes
  add(rerun);
  const std::vector<HistoryRow> rows = store->history({});
  const std::vector<CommitLine> lines = group_by_commit(rows);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].commit.sha, fake_sha(3));
  EXPECT_EQ(lines[1].commit.sha, fake_sha(2));
  EXPECT_EQ(lines[2].commit.sha, fake_sha(1));
  EXPECT_DOUBLE_EQ(*cell(lines[1], "balls").ratio, 0.95);
  EXPECT_EQ(lines[1].commit.subject, "commit 2");
  EXPECT_EQ(store->measurements({}).size(), 8u);  // every document's rows
  const auto last_two = store->history(query([](HistoryQuery& q) { q.last_commits = 2; }));
  EXPECT_EQ(group_by_commit(last_two).size(), 2u);
}

TEST_F(StoreHistory, RowsCarryTheNumbersHistoryShows) {
  DocumentSpec spec = commit(1, "10", 0.5);
  spec.scenes = {{"balls", 0.5, 0.04, 1.25, 0.02, ImageVerdict::fail}};
  add(spec);
  const std::vector<HistoryRow> rows = store->history({});
  ASSERT_EQ(rows.size(), 1u);
  const HistoryRow& row = rows[0];
  EXPECT_EQ(row.short_sha, fake_sha(1).substr(0, 7));
  EXPECT_EQ(row.branch, "main");
  EXPECT_EQ(*row.commit_unix, *parse_iso8601_unix("2026-03-10T08:00:00Z"));
  EXPECT_DOUBLE_EQ(*row.ratio, 0.5);
  EXPECT_DOUBLE_EQ(*row.ratio_lower, 0.48);
  EXPECT_DOUBLE_EQ(*row.ratio_upper, 0.52);
  EXPECT_DOUBLE_EQ(*row.baseline_median_seconds, 1.25);
  EXPECT_EQ(row.image_verdict, "fail");
  EXPECT_DOUBLE_EQ(*row.image_max_error, 0.02);
  EXPECT_DOUBLE_EQ(*row.image_rms_error, 0.005);
  EXPECT_EQ(row.machine_hostname, "ci-runner-1");
  EXPECT_EQ(row.machine_cpu_model, "Test CPU 3000");
  EXPECT_FALSE(row.stored_at.empty());
}

TEST_F(StoreHistory, FiltersByBranchSceneRoleAndDirtiness) {
  add(commit(1, "10", 1.0), "main");
  add(commit(2, "11", 1.0), "feature");
  DocumentSpec compare = commit(3, "12", 0.9);
  compare.kind = DocumentKind::compare;
  compare.roles = {Role::base, Role::head};
  add(compare, "main");
  DocumentSpec dirty = commit(4, "13", 0.7);
  dirty.dirty = true;
  add(dirty, "main");

  const auto history_where = [&](auto set) { return store->history(query(set)); };
  EXPECT_EQ(group_by_commit(history_where([](HistoryQuery& q) { q.branch = "feature"; })).size(),
            1u);
  const auto gears = history_where([](HistoryQuery& q) { q.scenes = {"gears"}; });
  EXPECT_EQ(scene_ids(gears), std::vector<std::string>{"gears"});
  const auto heads = group_by_commit(history_where([](HistoryQuery& q) { q.role = "head"; }));
  ASSERT_EQ(heads.size(), 1u);
  EXPECT_EQ(heads[0].commit.sha, fake_sha(3));
  EXPECT_EQ(group_by_commit(store->history({})).size(), 2u);  // tracer rows, clean trees
  const auto with_dirty =
      group_by_commit(history_where([](HistoryQuery& q) { q.include_dirty = true; }));
  ASSERT_EQ(with_dirty.size(), 3u);
  EXPECT_TRUE(with_dirty[0].commit.dirty);  // measured last
  // "any": base and head of the compare document are one commit, each scene once.
  EXPECT_EQ(history_where([](HistoryQuery& q) { q.role = "any"; }).size(), 3u * 2u);
}

TEST_F(StoreHistory, ShardsOfOneCommitJoinIntoOneLine) {
  DocumentSpec first = commit(1, "10", 1.0);
  first.shard = "1/2";
  first.scenes = {{"balls", 1.0}};
  DocumentSpec second = commit(1, "10", 1.0);
  second.scenes = {{"gears", 2.0}};
  add(first);
  add(second);
  const auto lines = group_by_commit(store->history({}));
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].scenes.size(), 2u);
}

TEST(History, TrendComparesWithThePreviousCommit) {
  std::vector<HistoryRow> rows;
  const double ratios[] = {1.0, 1.0, 1.1};  // oldest first
  for (int i = 0; i < 3; ++i) {
    HistoryRow row;
    row.sha = fake_sha(i);
    row.short_sha = row.sha.substr(0, 7);
    row.commit_unix = 1000 + i;
    row.scene_id = "balls";
    row.series_id = "balls-series";
    row.ratio = ratios[i];
    rows.push_back(row);
  }
  const auto lines = group_by_commit(latest_per_commit(rows, 0));
  const std::vector<SeriesColumn> columns = series_columns(rows);
  ASSERT_EQ(columns.size(), 1u);
  const SceneTrend trend = scene_trend(lines, columns[0]);
  EXPECT_EQ(trend.ratios, (std::vector<double>{1.0, 1.0, 1.1}));
  EXPECT_NEAR(*trend.change, 0.1, 1e-12);
  EXPECT_EQ(trend.arrow, "↑");
  EXPECT_EQ(trend.previous_short_sha, fake_sha(1).substr(0, 7));
  EXPECT_EQ(trend.sparkline, "▁▁█");
  SeriesColumn gears = columns[0];
  gears.series_id = "gears-series";
  EXPECT_FALSE(scene_trend(lines, gears).latest);
}

TEST(History, Sparkline) {
  EXPECT_EQ(sparkline({}), "");
  EXPECT_EQ(sparkline({2.0, 2.0}), "▄▄");
  EXPECT_EQ(sparkline({1.0, 2.0, 3.0}), "▁▅█");
  EXPECT_EQ(sparkline({3.0, 1.0}), "█▁");
}

TEST(StoreRows, Iso8601) {
  EXPECT_EQ(parse_iso8601_unix("1970-01-01T00:00:00Z"), 0);
  EXPECT_EQ(parse_iso8601_unix("2000-03-01T00:00:00+00:00"), 951868800);
  EXPECT_EQ(parse_iso8601_unix("2000-03-01T01:30:00+01:30"), 951868800);
  EXPECT_EQ(parse_iso8601_unix("2000-02-29T19:00:00-0500"), 951868800);
  EXPECT_EQ(parse_iso8601_unix("2000-03-01T00:00:00.250Z"), 951868800);
  EXPECT_FALSE(parse_iso8601_unix(""));
  EXPECT_FALSE(parse_iso8601_unix("2000-03-01"));
  EXPECT_FALSE(parse_iso8601_unix("2000-13-01T00:00:00Z"));
  EXPECT_FALSE(parse_iso8601_unix("2000-03-01T00:00:00"));
}

TEST(StoreRows, ShortRefName) {
  EXPECT_EQ(short_ref_name("refs/heads/main"), "main");
  EXPECT_EQ(short_ref_name("refs/remotes/origin/topic/x"), "origin/topic/x");
  EXPECT_EQ(short_ref_name("refs/tags/v1.0"), "v1.0");
  EXPECT_EQ(short_ref_name(""), "");
}

TEST(StoreRows, ContentHashIgnoresNothingAndNamesTheDocument) {
  DocumentSpec spec = commit(1, "10", 1.0);
  const DocumentRows a = document_rows(make_document(spec), "main", "t");
  spec.scenes[0].ratio = 1.0000001;
  const DocumentRows b = document_rows(make_document(spec), "main", "t");
  EXPECT_NE(a.document.content_sha256, b.document.content_sha256);
  EXPECT_EQ(
      a.document.content_sha256,
      document_rows(make_document(commit(1, "10", 1.0)), "other", "later").document.content_sha256);
  EXPECT_EQ(a.scenes.size(), 2u);
  EXPECT_EQ(a.revisions.size(), 1u);
}

}  // namespace
}  // namespace raygate::test

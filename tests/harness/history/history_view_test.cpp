// history/: the history view of stored documents (one table per repository and adapter, as text
// and JSON), a stored row as a trend point, and the trends a new document's reports draw from the
// store, including a store that cannot be read.
#include <gtest/gtest.h>

#include "core/fs.h"
#include "history/history_view.h"
#include "history/store_trends.h"
#include "results_fixture.h"
#include "store/store.h"

namespace raygate::test {
namespace {

DocumentSpec commit(int seed, const std::string& day, double ratio) {
  return march_commit(seed, day, ratio);
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

class HistoryFromStore : public ::testing::Test {
 protected:
  HistoryFromStore() {
    const auto store = open_store(path.string());
    store->add(make_document(commit(1, "10", 1.00)), "main");
    store->add(make_document(commit(2, "12", 0.90)), "main");
    store->add(make_document(commit(3, "14", 0.99)), "main");
  }
  HistoryView view() const {
    const auto store = open_store(path.string(), StoreOpen::must_exist);
    HistoryView v = make_history_view(store->history({}), 0, {});
    v.store = path.string();
    v.role = "tracer";
    return v;
  }
  TempDir dir;
  std::filesystem::path path = dir.path() / "results.db";
};

TEST_F(HistoryFromStore, OneTableNewestCommitFirstWithEachSeriesTrend) {
  const HistoryView v = view();
  ASSERT_EQ(v.tables.size(), 1u);
  const HistoryTable& table = v.tables[0];
  EXPECT_EQ(table.adapter_name, "cmake-nff");
  ASSERT_EQ(table.lines.size(), 3u);
  EXPECT_EQ(table.lines[0].commit.sha, fake_sha(3));
  ASSERT_EQ(table.trends.size(), 2u);
  EXPECT_EQ(table.trends[0].ratios, (std::vector<double>{1.00, 0.90, 0.99}));
  EXPECT_EQ(table.baseline_versions, 1u);

  const std::string text = history_table(v);
  EXPECT_TRUE(has(text, "adapter cmake-nff: 3 commits, newest first")) << text;
  EXPECT_TRUE(has(text, "0.990 ±1.0%")) << text;  // ratio and its CI half-width
  EXPECT_TRUE(has(text, "+10.0% ↑ vs " + fake_sha(2).substr(0, 7))) << text;
  const nlohmann::json json = history_json(v);
  EXPECT_EQ(json["tables"][0]["commits"].size(), 3u);
  EXPECT_EQ(json["tables"][0]["trends"]["balls"]["latest"], 0.99);
  EXPECT_TRUE(json["machine_drift"].is_null());
}

TEST_F(HistoryFromStore, ThePageDrawsOnePlotPerSeries) {
  const std::string page = history_html(view());
  EXPECT_TRUE(page.starts_with("<!DOCTYPE html>"));
  std::size_t plots = 0;
  for (std::size_t at = page.find("<svg"); at != std::string::npos;
       at = page.find("<svg", at + 1)) {
    ++plots;
  }
  EXPECT_EQ(plots, 2u);
  EXPECT_TRUE(has(page, "commit 3")) << "the commit table names the subjects";
}

TEST_F(HistoryFromStore, ANewDocumentsTrendIsItsOwnSeriesOldestFirst) {
  const StoreTrends found = trends_from_store(path, make_document(commit(4, "16", 1.0)));
  EXPECT_EQ(found.warning, "");
  ASSERT_EQ(found.trends.size(), 2u);
  EXPECT_EQ(found.trends[0].scene, "balls");
  ASSERT_EQ(found.trends[0].points.size(), 3u);
  EXPECT_EQ(found.trends[0].points[0].ratio, 1.00);
  EXPECT_EQ(found.trends[0].points[2].ratio, 0.99);

  DocumentSpec other = commit(4, "16", 1.0);
  other.adapter = "make-nff";  // another adapter's history is not this document's trend
  EXPECT_TRUE(trends_from_store(path, make_document(other)).trends.empty());
}

// A report about commit 2 shows the history up to commit 2, not the newest commits of the store
// (issue 26: the compare's report marked a commit outside the compare).
TEST_F(HistoryFromStore, TheTrendWindowEndsAtTheDocumentsOwnCommit) {
  const StoreTrends found = trends_from_store(path, make_document(commit(2, "12", 0.90)), 2);
  ASSERT_EQ(found.trends.size(), 2u);
  ASSERT_EQ(found.trends[0].points.size(), 2u);
  EXPECT_EQ(found.trends[0].points[0].ratio, 1.00);
  EXPECT_EQ(found.trends[0].points[1].ratio, 0.90);
  EXPECT_EQ(found.trends[0].points[1].sha, fake_sha(2));
}

// Another build of the same adapter name (other CMake flags) is another series: its document
// says what it measured, and rows of older documents, which do not, keep their own series.
TEST_F(HistoryFromStore, AnotherBuildOfTheSameAdapterIsAnotherSeries) {
  ResultsDocument flagged = make_document(commit(4, "16", 1.0));
  for (RevisionRecord& revision : flagged.revisions)
    revision.adapter_measurement = "0123456789abcdef";
  EXPECT_TRUE(trends_from_store(path, flagged).trends.empty());
  open_store(path.string())->add(flagged, "main");
  ResultsDocument again = make_document(commit(5, "18", 1.0));
  for (RevisionRecord& revision : again.revisions)
    revision.adapter_measurement = "0123456789abcdef";
  open_store(path.string())->add(again, "main");
  const StoreTrends found = trends_from_store(path, again);
  ASSERT_EQ(found.trends.size(), 2u);
  ASSERT_EQ(found.trends[0].points.size(), 2u);  // commits 4 and 5, none of the older build
  EXPECT_EQ(found.trends[0].points[0].sha, fake_sha(4));
  const StoreTrends old = trends_from_store(path, make_document(commit(3, "14", 0.99)));
  ASSERT_EQ(old.trends.size(), 2u);
  EXPECT_EQ(old.trends[0].points.size(), 3u);  // commits 1 to 3, as before
}

// Peak memory (issue 27): stored with each run, shown beside the ratio in every form.
TEST(HistoryMemory, PeaksAreShownInTheTableTheJsonTheTrendAndThePage) {
  TempDir dir;
  const auto path = dir.path() / "results.db";
  const auto store = open_store(path.string());
  const long peaks_kib[] = {8 * 1024, 8 * 1024 + 40, 58 * 1024};
  for (int seed = 1; seed <= 3; ++seed) {
    DocumentSpec spec = commit(seed, std::to_string(10 + 2 * seed), 1.0);
    for (SceneSpec& scene : spec.scenes) scene.peak_kib = peaks_kib[seed - 1];
    store->add(make_document(spec), "main");
  }
  store->add(make_document(commit(4, "20", 1.0)), "main");  // from before raygate-meter: no peak
  HistoryView v = make_history_view(store->history({}), 0, {});
  v.store = path.string();
  v.role = "tracer";
  const SceneTrend& balls = v.tables.at(0).trends.at(0);
  EXPECT_EQ(balls.peaks_kib, (std::vector<double>{8192, 8232, 59392}));
  ASSERT_TRUE(balls.peak_change);
  EXPECT_NEAR(*balls.peak_change, 59392.0 / 8232.0 - 1.0, 1e-12);
  EXPECT_EQ(balls.memory_arrow, "↑");

  const std::string text = history_table(v);
  EXPECT_TRUE(has(text, "peak")) << text;
  EXPECT_TRUE(has(text, "58.0 MiB")) << text;
  EXPECT_TRUE(has(text, "memory (peak resident, the tracer's own; oldest -> newest):")) << text;
  EXPECT_TRUE(has(text, "58.0 MiB  +621.5% ↑ vs " + fake_sha(2).substr(0, 7))) << text;
  const nlohmann::json json = history_json(v);
  const nlohmann::json& newest = json["tables"][0]["commits"][0]["scenes"]["balls"];
  EXPECT_TRUE(newest["memory"]["peak_kib"].is_null());  // commit 4
  EXPECT_EQ(json["tables"][0]["commits"][1]["scenes"]["balls"]["memory"]["peak_kib"], 59392.0);
  EXPECT_EQ(json["tables"][0]["trends"]["balls"]["latest_peak_kib"], 59392.0);

  const std::string page = history_html(v);
  EXPECT_TRUE(has(page, "class=\"plot trend-plot memory-plot\"")) << page;
  EXPECT_TRUE(has(page, "peak memory (MiB) of balls over 3 commits")) << page;
  EXPECT_TRUE(has(page, "peak 58.0 MiB")) << page;  // the newest point's tooltip
}

TEST(TrendPoint, AMemoryPointIsInMebibytesAndFlaggedWhenItsVerdictRegressed) {
  HistoryRow row;
  row.short_sha = "abc1234";
  row.peak_memory_kib = 59392;
  row.memory_change = 6.25;
  row.memory_verdict = "REGRESSED";
  const TrendPoint point = memory_trend_point(row);
  EXPECT_DOUBLE_EQ(point.ratio, 58.0);
  EXPECT_TRUE(point.flagged);
  EXPECT_EQ(point.note, "memory REGRESSED (+625.0% against base)");
}

TEST(StoreTrends, NoStoreIsNoTrendAndAnUnreadableOneIsAWarning) {
  TempDir dir;
  const ResultsDocument document = make_document(commit(1, "10", 1.0));
  const StoreTrends none = trends_from_store(dir.path() / "absent.db", document);
  EXPECT_TRUE(none.trends.empty());
  EXPECT_EQ(none.warning, "");
  write_file_atomically(dir.path() / "garbage.db", "not a database, not even close\n");
  const StoreTrends unreadable = trends_from_store(dir.path() / "garbage.db", document);
  EXPECT_TRUE(unreadable.trends.empty());
  EXPECT_TRUE(has(unreadable.warning, "no trends from " + (dir.path() / "garbage.db").string()))
      << unreadable.warning;
}

TEST(TrendPoint, AFailedImageIsFlaggedWithItsError) {
  HistoryRow row;
  row.short_sha = "abc1234";
  row.ratio = 1.2;
  row.ratio_lower = 1.1;
  row.image_verdict = "fail";
  row.image_max_error = 0.25;
  const TrendPoint point = trend_point(row);
  EXPECT_TRUE(point.flagged);
  EXPECT_EQ(point.lower, 1.1);
  EXPECT_EQ(point.upper, 1.2);  // no upper end stored: the ratio itself
  EXPECT_EQ(point.note, "image max error 0.2500 (fail)");
  row.image_verdict = "pass";
  EXPECT_FALSE(trend_point(row).flagged);
}

TEST(HistoryText, WidthsCountCodePointsNotBytes) {
  EXPECT_EQ(pad_right("→x", 4), "→x  ");
  EXPECT_EQ(truncate_text("ünïcödé subject", 5), "ünïc…");
  EXPECT_EQ(truncate_text("short", 5), "short");
  EXPECT_EQ(short_repository("root:0123456789abcdef0123"), "root:0123456789ab");
  EXPECT_EQ(short_repository("/srv/git/tracer"), "/srv/git/tracer");
}

}  // namespace
}  // namespace raygate::test

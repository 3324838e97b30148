// History series (results/series.h): which measurements may be compared over commits. Two tracers'
// repositories and two adapters in one store give four separate tables and trends; any part of
// the key (repository, adapter, suite, scene settings, timing, baseline) starts a new series;
// drift compares a series only with itself; history filters by the parts.
#include <gtest/gtest.h>

#include <set>

#include "core/fs.h"
#include "results_fixture.h"
#include "store/drift.h"
#include "store/history.h"
#include "results/series.h"
#include "store/store.h"
#include "store/store_rows.h"

namespace raygate::test {
namespace {

const std::string kRepoA = "root:" + std::string(40, 'a');
const std::string kRepoB = "root:" + std::string(40, 'b');

DocumentSpec teapot(int seed, int day, double ratio, const std::string& repository,
                    const std::string& adapter = "cmake-nff") {
  DocumentSpec spec;
  spec.sha = fake_sha(seed);
  spec.subject = "commit " + std::to_string(seed);
  spec.commit_time = "2026-06-" + std::to_string(10 + day) + "T10:00:00+00:00";
  spec.started_at = "2026-06-" + std::to_string(10 + day) + "T12:00:00Z";
  spec.repository_id = repository;
  spec.adapter = adapter;
  spec.scenes = {{"teapot", ratio}};
  return spec;
}

std::string series_of(const ResultsDocument& document) {
  return series_key(document, document.revisions.at(0), document.scenes.at(0)).id();
}

TEST(SeriesKey, EveryPartOfTheKeyStartsANewSeries) {
  const ResultsDocument base = make_document(teapot(1, 1, 1.0, kRepoA));
  const std::string id = series_of(base);
  EXPECT_EQ(id.size(), 16u);
  EXPECT_EQ(series_of(make_document(teapot(2, 2, 1.7, kRepoA))), id);  // another commit, same

  const auto changed = [&](auto change) {
    ResultsDocument d = base;
    change(d);
    return series_of(d);
  };
  EXPECT_NE(changed([](ResultsDocument& d) { d.revisions[0].repository_id = kRepoB; }), id);
  EXPECT_NE(changed([](ResultsDocument& d) { d.revisions[0].adapter_name = "meson"; }), id);
  EXPECT_NE(changed([](ResultsDocument& d) { d.suite = "full"; }), id);
  EXPECT_NE(changed([](ResultsDocument& d) { d.scenes[0].entry.size = 2; }), id);
  EXPECT_NE(changed([](ResultsDocument& d) { d.scenes[0].entry.width = 128; }), id);
  EXPECT_NE(changed([](ResultsDocument& d) { d.scenes[0].entry.height = 128; }), id);
  EXPECT_NE(changed([](ResultsDocument& d) { d.baseline.sampling = "corners"; }), id);
  EXPECT_NE(changed([](ResultsDocument& d) { d.settings.metric = "cpu"; }), id);
  EXPECT_NE(changed([](ResultsDocument& d) { d.settings.tracer_clock = "process-cpu"; }), id);
  EXPECT_NE(changed([](ResultsDocument& d) { d.baseline.timing = "in-process"; }), id);
  EXPECT_NE(changed([](ResultsDocument& d) { d.baseline.source_sha256 = std::string(64, 'c'); }),
            id);
  EXPECT_NE(changed([](ResultsDocument& d) { d.baseline.accel = "bvh"; }), id);
  // What is not part of the key: the machine, the commit, the numbers.
  EXPECT_EQ(changed([](ResultsDocument& d) { d.machine["hostname"] = "other"; }), id);
}

TEST(SeriesKey, RepositoryFromTheRecordedIdentityElseTheLocation) {
  RevisionRecord r;
  r.repository = "/home/me/tracer/../tracer";
  EXPECT_EQ(repository_key(r), "path:/home/me/tracer");
  r.repository = "git@GitHub.com:me/tracer.git";
  EXPECT_EQ(repository_key(r), "url:github.com/me/tracer");
  r.repository = "https://github.com/me/tracer/";
  EXPECT_EQ(repository_key(r), "url:github.com/me/tracer");
  r.repository_id = kRepoA;
  EXPECT_EQ(repository_key(r), kRepoA);
  EXPECT_EQ(repository_key(RevisionRecord{}), "unknown");
}

TEST(SeriesKey, RowsCarryTheirSeries) {
  const ResultsDocument d = make_document(teapot(1, 1, 1.0, kRepoA));
  const DocumentRows rows = document_rows(d, "main", "t");
  EXPECT_EQ(rows.revisions.at(0).repository_key, kRepoA);
  EXPECT_EQ(rows.scenes.at(0).series_id, series_of(d));
  EXPECT_EQ(rows.scenes.at(0).scene_settings, "scene=teapot size=1 64x64 sampling=center");
  EXPECT_EQ(rows.document.timing, "- process-wall");
  EXPECT_EQ(rows.document.baseline_accel, "none");
}

class StoreSeries : public ::testing::Test {
 protected:
  void SetUp() override { store = open_store((dir.path() / "results.db").string()); }
  // Tracer A (two adapters) and tracer B (two adapters), interleaved in time. B's teapot is
  // 1.718x A's: a mixed trend would say "+71.8%".
  void two_tracers_two_adapters() {
    store->add(make_document(teapot(1, 1, 1.00, kRepoA)), "main");
    store->add(make_document(teapot(2, 2, 1.718, kRepoB)), "main");
    store->add(make_document(teapot(3, 3, 1.01, kRepoA)), "main");
    store->add(make_document(teapot(4, 4, 1.718, kRepoB)), "main");
    store->add(make_document(teapot(1, 5, 2.00, kRepoA, "meson")), "main");
    store->add(make_document(teapot(3, 6, 2.02, kRepoA, "meson")), "main");
    store->add(make_document(teapot(2, 7, 3.00, kRepoB, "meson")), "main");
  }
  TempDir dir;
  std::unique_ptr<ResultsStore> store;
};

TEST_F(StoreSeries, TwoTracersAndTwoAdaptersGiveSeparateTablesAndTrends) {
  two_tracers_two_adapters();
  const std::vector<HistoryGroup> groups = group_by_repository_and_adapter(store->measurements({}));
  ASSERT_EQ(groups.size(), 4u);
  // Newest first: B/meson (day 7), A/meson (day 6), B/cmake-nff (day 4), A/cmake-nff (day 3).
  EXPECT_EQ(groups[0].repository_key, kRepoB);
  EXPECT_EQ(groups[0].adapter_name, "meson");
  EXPECT_EQ(groups[1].repository_key, kRepoA);
  EXPECT_EQ(groups[1].adapter_name, "meson");
  EXPECT_EQ(groups[3].repository_key, kRepoA);
  EXPECT_EQ(groups[3].adapter_name, "cmake-nff");

  const auto trend_of = [](const HistoryGroup& group) {
    const std::vector<HistoryRow> rows = latest_per_commit(group.rows, 0);
    const std::vector<SeriesColumn> columns = series_columns(rows);
    EXPECT_EQ(columns.size(), 1u);
    return scene_trend(group_by_commit(rows), columns.at(0));
  };
  const SceneTrend a = trend_of(groups[3]);
  EXPECT_EQ(a.ratios, (std::vector<double>{1.00, 1.01}));
  EXPECT_NEAR(*a.change, 0.01, 1e-9);
  EXPECT_EQ(a.previous_short_sha, fake_sha(1).substr(0, 7));
  const SceneTrend b = trend_of(groups[2]);
  EXPECT_EQ(b.ratios, (std::vector<double>{1.718, 1.718}));
  EXPECT_NEAR(*b.change, 0.0, 1e-12);
  EXPECT_EQ(b.previous_short_sha, fake_sha(2).substr(0, 7));
  EXPECT_EQ(trend_of(groups[0]).ratios, std::vector<double>{3.00});
  EXPECT_FALSE(trend_of(groups[0]).change);

  // One commit measured by two adapters keeps both measurements in a store-wide history.
  std::size_t commit_one = 0;
  for (const HistoryRow& row : store->history({})) commit_one += row.sha == fake_sha(1) ? 1 : 0;
  EXPECT_EQ(commit_one, 2u);
}

TEST_F(StoreSeries, HistoryFiltersByRepositoryAdapterSuiteAndSeries) {
  two_tracers_two_adapters();
  HistoryQuery q;
  q.repository = std::string(12, 'b');  // part of B's root commit, as the tables show it
  for (const HistoryRow& row : store->history(q)) EXPECT_EQ(row.repository_key, kRepoB);
  EXPECT_EQ(store->history(q).size(), 3u);
  q.adapter = "meson";
  ASSERT_EQ(store->history(q).size(), 1u);
  EXPECT_DOUBLE_EQ(*store->history(q)[0].ratio, 3.0);
  q = {};
  q.suite = "full";
  EXPECT_TRUE(store->history(q).empty());
  q = {};
  q.series = series_of(make_document(teapot(1, 1, 1.0, kRepoA))).substr(0, 6);
  const std::vector<HistoryRow> a = store->history(q);
  ASSERT_EQ(a.size(), 2u);
  for (const HistoryRow& row : a) {
    EXPECT_EQ(row.adapter_name, "cmake-nff");
    EXPECT_EQ(row.suite, "ci");
    EXPECT_EQ(row.scene_settings, "scene=teapot size=1 64x64 sampling=center");
  }
}

TEST_F(StoreSeries, ASceneWithSeveralSeriesInOneTableGetsAColumnEach) {
  DocumentSpec ci = teapot(1, 1, 1.0, kRepoA);
  DocumentSpec full = teapot(2, 2, 1.5, kRepoA);
  full.suite = "full";
  store->add(make_document(ci), "main");
  store->add(make_document(full), "main");
  const std::vector<HistoryRow> rows = store->history({});
  const std::vector<SeriesColumn> columns = series_columns(rows);
  ASSERT_EQ(columns.size(), 2u);
  EXPECT_EQ(columns[0].label, "teapot [suite ci]");
  EXPECT_EQ(columns[1].label, "teapot [suite full]");
  const std::vector<CommitLine> lines = group_by_commit(rows);
  EXPECT_EQ(scene_trend(lines, columns[0]).ratios, std::vector<double>{1.0});
  EXPECT_EQ(scene_trend(lines, columns[1]).ratios, std::vector<double>{1.5});
  EXPECT_EQ(scene_trend(lines, columns[1]).label, "teapot [suite full]");
}

// Issue 40: two series of one scene that differ only in how the adapter builds or runs the
// tracer (the series key's measurement) were told apart by 8 digits of their id. Their labels
// say what differs and which commits each covers.
TEST_F(StoreSeries, SeriesThatDifferOnlyInTheAdapterAreNamedByTheirCommits) {
  for (const auto& [seed, measurement] : {std::pair{1, "O2"}, {2, "O2"}, {3, "O3"}}) {
    ResultsDocument document = make_document(teapot(seed, seed, 1.0, kRepoA));
    document.revisions.at(0).adapter_measurement = measurement;
    store->add(document, "main");
  }
  const std::vector<SeriesColumn> columns = series_columns(store->history({}));
  ASSERT_EQ(columns.size(), 2u);
  std::set<std::string> labels;
  for (const SeriesColumn& column : columns) labels.insert(column.label);
  const auto short_sha = [](int seed) { return fake_sha(seed).substr(0, 7); };
  EXPECT_EQ(labels, (std::set<std::string>{
                        "teapot [adapter settings of " + short_sha(1) + ".." + short_sha(2) + "]",
                        "teapot [adapter settings of " + short_sha(3) + "]"}));
}

// Store-wide (raygate alert), one scene of two repositories: the repository tells them apart.
TEST_F(StoreSeries, SeriesOfTwoRepositoriesAreNamedByTheRepository) {
  store->add(make_document(teapot(1, 1, 1.0, kRepoA)), "main");
  store->add(make_document(teapot(2, 2, 1.0, kRepoB)), "main");
  std::set<std::string> labels;
  for (const SeriesColumn& column : series_columns(store->history({}))) {
    labels.insert(column.label);
  }
  EXPECT_EQ(labels, (std::set<std::string>{"teapot [repository " + kRepoA.substr(0, 17) + "]",
                                           "teapot [repository " + kRepoB.substr(0, 17) + "]"}));
}

TEST_F(StoreSeries, DriftComparesASeriesOnlyWithItself) {
  // A's history at 1 s of baseline per scene; then B, on the same machine, at 0.8 s with its
  // own steady ratio: B has no earlier history of its own, so nothing drifted.
  DocumentSpec a1 = teapot(1, 1, 1.0, kRepoA);
  DocumentSpec a2 = teapot(3, 2, 1.0, kRepoA);
  DocumentSpec b = teapot(2, 3, 1.0, kRepoB);
  b.scenes[0].baseline_seconds = 0.8;
  for (const DocumentSpec& spec : {a1, a2, b}) store->add(make_document(spec), "main");
  EXPECT_FALSE(detect_machine_drift(store->measurements({})));
  // The same move within A's own series is the machine.
  DocumentSpec a3 = teapot(5, 4, 1.0, kRepoA);
  a3.scenes[0].baseline_seconds = 0.8;
  store->add(make_document(a3), "main");
  EXPECT_TRUE(detect_machine_drift(store->measurements({})));
}

}  // namespace
}  // namespace raygate::test

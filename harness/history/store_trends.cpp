#include "history/store_trends.h"

#include <algorithm>
#include <map>

#include "core/error.h"
#include "history/history_view.h"
#include "results/series.h"
#include "store/postgres_url.h"
#include "store/store.h"

namespace raygate {

namespace {

// The rows of the measured revision's repository, adapter and suite, oldest commit first.
std::vector<HistoryRow> stored_rows(const std::filesystem::path& store,
                                    const ResultsDocument& document,
                                    const RevisionRecord& measured, std::size_t commits) {
  HistoryQuery query;
  query.role = "any";
  query.last_commits = commits;
  query.repository = repository_key(measured);
  query.adapter = measured.adapter_name;
  query.suite = document.suite;
  std::vector<HistoryRow> rows = open_store(store.string(), StoreOpen::must_exist)->history(query);
  std::sort(rows.begin(), rows.end(), [](const HistoryRow& a, const HistoryRow& b) {
    return a.commit_unix.value_or(0) < b.commit_unix.value_or(0);
  });
  return rows;
}

}  // namespace

StoreTrends trends_from_store(const std::filesystem::path& store, const ResultsDocument& document,
                              std::size_t commits) {
  const bool team_store = is_postgresql_url(store.string());
  if (store.empty() || (!team_store && !std::filesystem::exists(store))) return {};
  // The document's own series, scene by scene: another tracer's, adapter's or setting's history
  // is not this one's trend.
  const RevisionRecord* measured = document.revision("tracer");
  if (measured == nullptr) measured = document.revision("head");
  if (measured == nullptr) return {};
  std::map<std::string, std::string> wanted_series;  // scene id -> series id
  for (const SceneResult& scene : document.scenes) {
    wanted_series[scene.entry.id] = series_key(document, *measured, scene).id();
  }
  std::vector<HistoryRow> rows;
  try {
    rows = stored_rows(store, document, *measured, commits);
  } catch (const Error& e) {
    return {{}, "no trends from " + redact_postgresql_url(store.string()) + ": " + e.what()};
  }
  std::map<std::string, TrendSeries> by_scene;
  for (const HistoryRow& row : rows) {
    const auto wanted = wanted_series.find(row.scene_id);
    if (!row.ratio || wanted == wanted_series.end() || row.series_id != wanted->second) continue;
    TrendSeries& series = by_scene[row.scene_id];
    series.scene = row.scene_id;
    series.points.push_back(trend_point(row));
  }
  StoreTrends found;
  for (auto& [scene, series] : by_scene) {
    if (series.points.size() >= 2) found.trends.push_back(std::move(series));
  }
  return found;
}

}  // namespace raygate

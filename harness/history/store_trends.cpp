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

// The rows of the measured revision's repository, adapter and suite, oldest commit first: all
// of them, so the window can be placed around the document's own commits (window_of).
std::vector<HistoryRow> stored_rows(const std::filesystem::path& store,
                                    const ResultsDocument& document,
                                    const RevisionRecord& measured) {
  HistoryQuery query;
  query.role = "any";
  query.last_commits = 0;
  query.repository = repository_key(measured);
  query.adapter = measured.adapter_name;
  query.suite = document.suite;
  std::vector<HistoryRow> rows = open_store(store.string(), StoreOpen::must_exist)->history(query);
  std::sort(rows.begin(), rows.end(), [](const HistoryRow& a, const HistoryRow& b) {
    return a.commit_unix.value_or(0) < b.commit_unix.value_or(0);
  });
  return rows;
}

bool is_own_commit(const ResultsDocument& document, const TrendPoint& point) {
  for (const RevisionRecord& revision : document.revisions) {
    if (!point.sha.empty() && point.sha == revision.worktree.sha) return true;
  }
  return false;
}

// At most `commits` points (more only to reach both of the document's commits) ending at the
// newest of the document's own commits, or at the newest point when none of them is stored: a
// compare of an older pull request shows its base and head, not the newest commits of the store.
void window_of(TrendSeries& series, const ResultsDocument& document, std::size_t commits) {
  std::vector<TrendPoint>& p = series.points;
  std::size_t first_own = p.size(), last_own = p.size();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!is_own_commit(document, p[i])) continue;
    if (first_own == p.size()) first_own = i;
    last_own = i;
  }
  const std::size_t end = last_own == p.size() ? p.size() : last_own + 1;
  std::size_t begin = end > commits ? end - commits : 0;
  if (first_own < begin) begin = first_own;
  p = std::vector<TrendPoint>(p.begin() + static_cast<long>(begin),
                              p.begin() + static_cast<long>(end));
}

}  // namespace

StoreTrends trends_from_store(const std::filesystem::path& store, const ResultsDocument& document,
                              std::size_t commits) {
  const bool team_store = is_postgresql_url(store.string());
  if (store.empty() || (!team_store && !std::filesystem::exists(store))) return {};
  // The document's own series, scene by scene: another tracer's, adapter's or setting's history
  // is not this one's trend.
  const RevisionRecord* measured = document.revision(Role::tracer);
  if (measured == nullptr) measured = document.revision(Role::head);
  if (measured == nullptr) return {};
  std::map<std::string, std::string> wanted_series;  // scene id -> series id
  for (const SceneResult& scene : document.scenes) {
    wanted_series[scene.entry.id] = series_key(document, *measured, scene).id();
  }
  std::vector<HistoryRow> rows;
  try {
    rows = stored_rows(store, document, *measured);
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
    window_of(series, document, commits);
    if (series.points.size() >= 2) found.trends.push_back(std::move(series));
  }
  return found;
}

}  // namespace raygate

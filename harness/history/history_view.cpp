// The history view: stored rows grouped into one table per repository and adapter, and a stored
// row as a point of the report's trend plot.
#include "history/history_view.h"

#include "measure/change.h"

#include <fmt/core.h>

#include <set>

#include "compare/image_verdict.h"
#include "core/domain.h"

namespace raygate {

HistoryView make_history_view(const std::vector<HistoryRow>& measurements, std::size_t last_commits,
                              const std::vector<HistoryRow>& machine_rows) {
  HistoryView view;
  for (HistoryGroup& group : group_by_repository_and_adapter(measurements)) {
    HistoryTable table;
    table.repository_key = group.repository_key;
    table.adapter_name = group.adapter_name;
    const std::vector<HistoryRow> rows = latest_per_commit(std::move(group.rows), last_commits);
    table.lines = group_by_commit(rows);
    table.columns = series_columns(rows);
    for (const SeriesColumn& column : table.columns) {
      table.trends.push_back(scene_trend(table.lines, column));
    }
    std::set<std::string> baselines;
    for (const HistoryRow& row : rows) baselines.insert(row.baseline_sha256);
    table.baseline_versions = baselines.size();
    view.tables.push_back(std::move(table));
  }
  view.drift = detect_machine_drift(machine_rows);
  return view;
}

std::string short_repository(const std::string& repository_key) {
  constexpr std::string_view kRoot = "root:";
  if (repository_key.starts_with(kRoot) && repository_key.size() > kRoot.size() + 12) {
    return repository_key.substr(0, kRoot.size() + 12);
  }
  return repository_key;
}

namespace {

// The commit a point stands for, as every trend of it (ratio, memory) labels it.
TrendPoint commit_point(const HistoryRow& row) {
  TrendPoint point;
  point.sha = row.sha;
  point.short_sha = row.short_sha;
  point.subject = row.subject;
  point.commit_time = row.commit_time;
  return point;
}

}  // namespace

TrendPoint trend_point(const HistoryRow& row) {
  TrendPoint point = commit_point(row);
  point.ratio = *row.ratio;
  point.lower = row.ratio_lower.value_or(*row.ratio);
  point.upper = row.ratio_upper.value_or(*row.ratio);
  if (row.image_max_error) {
    point.note =
        fmt::format("image max error {:.4f} ({})", *row.image_max_error, row.image_verdict);
  }
  point.flagged = parse_image_verdict(row.image_verdict) == ImageVerdict::fail;
  return point;
}

TrendPoint memory_trend_point(const HistoryRow& row) {
  TrendPoint point = commit_point(row);
  const double mib = row.peak_memory_kib.value_or(0.0) / 1024.0;
  point.ratio = point.lower = point.upper = mib;
  if (!row.memory_verdict.empty() && row.memory_change) {
    point.note = fmt::format("memory {} ({:+.1f}% against base)", row.memory_verdict,
                             *row.memory_change * 100.0);
  }
  // The store keeps the verdict as its word (the SQL boundary); read it back as the type.
  point.flagged = change_verdict_named(row.memory_verdict) == ChangeVerdict::regressed;
  return point;
}

}  // namespace raygate

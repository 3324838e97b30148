// History over commits from stored measurements, the same for every backend: which measurement
// stands for a commit (the latest one of each series, so CI shards of one commit join up and a
// re-run supersedes), one table per repository and adapter, the commits as lines of a table, and
// each series' trend. Nothing here compares rows of different series (results/series.h).
#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "store/store.h"

namespace raygate {

// Rows in history order: newest commit first (by commit time; a tree with local changes by the
// time it was measured), then the latest measurement, then scene id.
void sort_history(std::vector<HistoryRow>& rows);

// A commit's identity in history: its sha, or for a tree with local changes its document, since
// two dirty measurements of one sha are different code.
std::string commit_key(const HistoryRow& row);

// Keeps the latest measurement of each (commit, series), newest commit first, and at most
// `last_commits` commits (0: all).
std::vector<HistoryRow> latest_per_commit(std::vector<HistoryRow> rows, std::size_t last_commits);

// One line of the history table: a commit and its scenes.
struct CommitLine {
  std::string key;
  HistoryRow commit;                         // the first row: sha, subject, dates, branch
  std::map<std::string, HistoryRow> scenes;  // by series id
};

// Groups rows from latest_per_commit into lines, keeping their order.
std::vector<CommitLine> group_by_commit(const std::vector<HistoryRow>& rows);

// Scene ids in the rows, sorted.
std::vector<std::string> scene_ids(const std::vector<HistoryRow>& rows);

// The rows of one repository and adapter: the unit `raygate history` shows a table for.
struct HistoryGroup {
  std::string repository_key;
  std::string adapter_name;
  std::vector<HistoryRow> rows;
};

// Rows split by (repository, adapter), each group keeping the rows' order; groups ordered by
// their newest row (recency as in sort_history).
std::vector<HistoryGroup> group_by_repository_and_adapter(const std::vector<HistoryRow>& rows);

// One column of a history table: one series.
struct SeriesColumn {
  std::string series_id;
  std::string scene_id;
  // The scene id, plus what tells this series from the others of the same scene id in the
  // table: "balls [suite full]", "balls [scene=balls size=2 0x0 sampling=center]".
  std::string label;
  HistoryRow sample;  // one row of the series, for its parts
};

// The series among rows, ordered by scene id, then by their parts.
std::vector<SeriesColumn> series_columns(const std::vector<HistoryRow>& rows);

struct SceneTrend {
  std::string series_id;
  std::string scene_id;
  std::string label;           // the column's (SeriesColumn::label)
  std::vector<double> ratios;  // oldest first, the commits that measured the scene
  std::optional<double> latest;
  std::optional<double> change;  // latest / previous - 1: +0.05 is 5% slower than before
  std::string previous_short_sha;
  std::string sparkline;  // one block character per ratio, oldest first
  std::string arrow;      // "↑" slower, "↓" faster, "→" within ±1%, "" no previous
  // Peak memory (issue 27), the same way: the commits that have the tracer's own peak.
  std::vector<double> peaks_kib;  // oldest first
  std::optional<double> latest_peak_kib;
  std::optional<double> peak_change;  // latest / previous - 1: +0.10 is 10% more memory
  std::string previous_peak_short_sha;
  std::string memory_sparkline;
  std::string memory_arrow;  // "↑" more, "↓" less, "→" within ±1%, "" no previous
};

inline constexpr double kTrendFlatFraction = 0.01;

// `lines` newest first, as group_by_commit gives them: the ratios of one series only.
SceneTrend scene_trend(const std::vector<CommitLine>& lines, const SeriesColumn& column);

// "▁▂▃▄▅▆▇█" scaled between the values' minimum and maximum; all equal: "▄" each.
std::string sparkline(const std::vector<double>& values);

}  // namespace raygate

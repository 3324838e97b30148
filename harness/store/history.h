// History over commits from stored measurements, the same for every backend: which measurement
// stands for a commit (the latest one of each scene, so CI shards of one commit join up and a
// re-run supersedes), the commits as lines of a table, and each scene's trend.
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

// Keeps the latest measurement of each (commit, scene), newest commit first, and at most
// `last_commits` commits (0: all).
std::vector<HistoryRow> latest_per_commit(std::vector<HistoryRow> rows, std::size_t last_commits);

// One line of the history table: a commit and its scenes.
struct CommitLine {
  std::string key;
  HistoryRow commit;                         // the first row: sha, subject, dates, branch
  std::map<std::string, HistoryRow> scenes;  // by scene id
};

// Groups rows from latest_per_commit into lines, keeping their order.
std::vector<CommitLine> group_by_commit(const std::vector<HistoryRow>& rows);

// Scene ids in the rows, sorted.
std::vector<std::string> scene_ids(const std::vector<HistoryRow>& rows);

struct SceneTrend {
  std::string scene_id;
  std::vector<double> ratios;  // oldest first, the commits that measured the scene
  std::optional<double> latest;
  std::optional<double> change;  // latest / previous - 1: +0.05 is 5% slower than before
  std::string previous_short_sha;
  std::string sparkline;  // one block character per ratio, oldest first
  std::string arrow;      // "↑" slower, "↓" faster, "→" within ±1%, "" no previous
};

inline constexpr double kTrendFlatFraction = 0.01;

// `lines` newest first, as group_by_commit gives them.
SceneTrend scene_trend(const std::vector<CommitLine>& lines, const std::string& scene_id);

// "▁▂▃▄▅▆▇█" scaled between the values' minimum and maximum; all equal: "▄" each.
std::string sparkline(const std::vector<double>& values);

}  // namespace raygate

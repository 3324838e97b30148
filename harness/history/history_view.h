// What `raygate history` shows: the commits of a history query as a terminal table with trends
// and notes, as JSON for machines, and as a self-contained HTML page of SVG plots.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "store/drift.h"
#include "report/reporter.h"
#include "store/history.h"

namespace raygate {

// One repository and adapter: its commits, its series as columns, each series' trend.
struct HistoryTable {
  std::string repository_key;
  std::string adapter_name;
  std::vector<CommitLine> lines;  // newest first
  std::vector<SeriesColumn> columns;
  std::vector<SceneTrend> trends;     // one per column, in `columns` order
  std::size_t baseline_versions = 0;  // distinct baseline sources among the rows
};

struct HistoryView {
  std::string store;  // where the rows came from
  std::string role;
  std::string branch;
  std::vector<HistoryTable> tables;  // newest first
  std::optional<MachineDrift> drift;
};

// `measurements` as ResultsStore::measurements gives them; each table keeps the latest
// measurement of each commit and series, at most `last_commits` commits (0: all).
HistoryView make_history_view(const std::vector<HistoryRow>& measurements, std::size_t last_commits,
                              const std::vector<HistoryRow>& machine_rows);

// "root:" and the first 12 digits of a root commit; other repository keys as they are.
std::string short_repository(const std::string& repository_key);

std::string history_table(const HistoryView& view);
nlohmann::json history_json(const HistoryView& view);
std::string history_html(const HistoryView& view);

// A measured row (ratio set) as a point of the report's trend plot (report/reporter.h).
TrendPoint trend_point(const HistoryRow& row);
// A row with a peak as a point of the memory trend: `ratio` holds the peak in MiB (issue 27);
// flagged when its memory verdict is REGRESSED.
TrendPoint memory_trend_point(const HistoryRow& row);

// Text helpers, public for tests: width in code points, not bytes.
std::string pad_right(const std::string& text, std::size_t width);
std::string truncate_text(const std::string& text, std::size_t max_code_points);

}  // namespace raygate

// What `raygate history` shows: the commits of a history query as a terminal table with trends
// and notes, as JSON for machines, and as a self-contained HTML page of SVG plots.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "store/drift.h"
#include "store/history.h"

namespace raygate::cli {

struct HistoryView {
  std::string store;  // where the rows came from
  std::string role;
  std::string branch;
  std::vector<CommitLine> lines;  // newest first
  std::vector<std::string> scenes;
  std::vector<SceneTrend> trends;  // one per scene, in `scenes` order
  std::optional<MachineDrift> drift;
  std::size_t baseline_versions = 0;  // distinct baseline sources among the rows
};

HistoryView make_history_view(const std::vector<HistoryRow>& rows,
                              const std::vector<HistoryRow>& machine_rows);

std::string history_table(const HistoryView& view);
nlohmann::json history_json(const HistoryView& view);
std::string history_html(const HistoryView& view);

// Text helpers, public for tests: width in code points, not bytes.
std::string pad_right(const std::string& text, std::size_t width);
std::string truncate_text(const std::string& text, std::size_t max_code_points);

}  // namespace raygate::cli

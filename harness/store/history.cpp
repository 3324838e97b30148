// Commits, lines and trends from history rows.
#include "store/history.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <tuple>

#include "store/store_rows.h"

namespace raygate {

namespace {

// Larger is newer: a commit by its commit time, a tree with local changes (no commit of its
// own) by the time it was measured.
auto recency(const HistoryRow& row) {
  const std::optional<std::int64_t> when =
      row.dirty || !row.commit_unix ? parse_iso8601_unix(row.measured_at) : row.commit_unix;
  return std::make_tuple(when.value_or(0), row.measured_at, row.document_id);
}

}  // namespace

void sort_history(std::vector<HistoryRow>& rows) {
  std::stable_sort(rows.begin(), rows.end(), [](const HistoryRow& a, const HistoryRow& b) {
    const auto ra = recency(a);
    const auto rb = recency(b);
    if (ra != rb) return ra > rb;
    return a.scene_id < b.scene_id;
  });
}

std::string commit_key(const HistoryRow& row) {
  return row.dirty ? "document " + std::to_string(row.document_id) : row.sha;
}

std::vector<HistoryRow> latest_per_commit(std::vector<HistoryRow> rows, std::size_t last_commits) {
  sort_history(rows);
  std::set<std::pair<std::string, std::string>> seen;  // (commit, scene)
  std::set<std::string> commits;
  std::vector<HistoryRow> out;
  for (HistoryRow& row : rows) {
    const std::string key = commit_key(row);
    if (!seen.insert({key, row.scene_id}).second) continue;
    if (!commits.contains(key) && last_commits != 0 && commits.size() == last_commits) continue;
    commits.insert(key);
    out.push_back(std::move(row));
  }
  return out;
}

std::vector<CommitLine> group_by_commit(const std::vector<HistoryRow>& rows) {
  std::vector<CommitLine> lines;
  std::map<std::string, std::size_t> index;
  for (const HistoryRow& row : rows) {
    const std::string key = commit_key(row);
    auto [at, fresh] = index.try_emplace(key, lines.size());
    if (fresh) lines.push_back({key, row, {}});
    lines[at->second].scenes.emplace(row.scene_id, row);
  }
  return lines;
}

std::vector<std::string> scene_ids(const std::vector<HistoryRow>& rows) {
  std::set<std::string> ids;
  for (const HistoryRow& row : rows) ids.insert(row.scene_id);
  return {ids.begin(), ids.end()};
}

SceneTrend scene_trend(const std::vector<CommitLine>& lines, const std::string& scene_id) {
  SceneTrend trend;
  trend.scene_id = scene_id;
  std::vector<std::string> shas;
  for (auto line = lines.rbegin(); line != lines.rend(); ++line) {
    const auto found = line->scenes.find(scene_id);
    if (found == line->scenes.end() || !found->second.ratio) continue;
    trend.ratios.push_back(*found->second.ratio);
    shas.push_back(found->second.short_sha);
  }
  trend.sparkline = sparkline(trend.ratios);
  if (trend.ratios.empty()) return trend;
  trend.latest = trend.ratios.back();
  if (trend.ratios.size() < 2) return trend;
  const double previous = trend.ratios[trend.ratios.size() - 2];
  trend.change = *trend.latest / previous - 1.0;
  trend.previous_short_sha = shas[shas.size() - 2];
  trend.arrow = *trend.change > kTrendFlatFraction    ? "↑"
                : *trend.change < -kTrendFlatFraction ? "↓"
                                                      : "→";
  return trend;
}

std::string sparkline(const std::vector<double>& values) {
  static constexpr std::array<const char*, 8> kBlocks = {"▁", "▂", "▃", "▄", "▅", "▆", "▇", "█"};
  if (values.empty()) return {};
  const auto [low, high] = std::minmax_element(values.begin(), values.end());
  const double span = *high - *low;
  std::string out;
  for (const double value : values) {
    if (!(span > 0.0)) {
      out += kBlocks[3];
      continue;
    }
    const double level = std::round((value - *low) / span * 7.0);
    out += kBlocks[static_cast<std::size_t>(std::clamp(level, 0.0, 7.0))];
  }
  return out;
}

}  // namespace raygate

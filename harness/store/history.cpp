// Commits, lines and trends from history rows.
#include "store/history.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <set>
#include <tuple>

#include "measure/memory_change.h"
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

// "root:" and 12 digits of a root commit; other repository keys as they are.
std::string repository_part(const HistoryRow& row) {
  const std::string& key = row.repository_key;
  return "repository " + (key.starts_with("root:") ? key.substr(0, 17) : key);
}

// The parts of a column's series that differ among `same_scene` (columns of one scene id).
std::string visible_parts(const SeriesColumn& column,
                          const std::vector<const SeriesColumn*>& same_scene) {
  using Part = std::string (*)(const HistoryRow&);
  const std::vector<Part> parts = {
      repository_part,
      [](const HistoryRow& r) { return "adapter " + r.adapter_name; },
      [](const HistoryRow& r) { return "suite " + r.suite; },
      [](const HistoryRow& r) { return r.scene_settings; },
      [](const HistoryRow& r) { return "timing " + r.timing; },
      [](const HistoryRow& r) {
        return "baseline " + r.baseline_sha256.substr(0, 8) + " accel=" + r.baseline_accel;
      },
  };
  std::string out;
  for (const Part part : parts) {
    const std::string mine = part(column.sample);
    const bool differs =
        std::any_of(same_scene.begin(), same_scene.end(),
                    [&](const SeriesColumn* other) { return part(other->sample) != mine; });
    if (differs) out += (out.empty() ? "" : ", ") + mine;
  }
  return out;
}

// The commits a series was measured at, oldest to newest: "3f2a1bc..9e8d7c6", or one.
std::string commit_span(const std::string& series_id, const std::vector<HistoryRow>& rows) {
  const HistoryRow* oldest = nullptr;
  const HistoryRow* newest = nullptr;
  for (const HistoryRow& row : rows) {
    if (row.series_id != series_id) continue;
    if (oldest == nullptr || recency(row) < recency(*oldest)) oldest = &row;
    if (newest == nullptr || recency(*newest) < recency(row)) newest = &row;
  }
  if (oldest == nullptr) return "";
  if (oldest->short_sha == newest->short_sha) return oldest->short_sha;
  return oldest->short_sha + ".." + newest->short_sha;
}

// What tells a column's series from the others of its scene id. When every part a row shows is
// the same, what differs is how the adapter builds or runs the tracer (the series key's
// measurement: flags, run command), or the row is from before series were kept: said in words,
// with the commits each covers, not as a hash.
std::string distinguishing_parts(const SeriesColumn& column,
                                 const std::vector<const SeriesColumn*>& same_scene,
                                 const std::vector<HistoryRow>& rows) {
  if (std::string parts = visible_parts(column, same_scene); !parts.empty()) return parts;
  if (column.series_id.starts_with("unknown-")) {
    return "stored before series were kept, document " + column.series_id.substr(8);
  }
  return "adapter settings of " + commit_span(column.series_id, rows);
}

// Labels each column with its scene id, and what sets it apart when a scene id has several.
void label_columns(std::vector<SeriesColumn>& columns, const std::vector<HistoryRow>& rows) {
  std::map<std::string, std::vector<const SeriesColumn*>> by_scene;
  for (const SeriesColumn& column : columns) by_scene[column.scene_id].push_back(&column);
  std::vector<std::string> labels;
  for (const SeriesColumn& column : columns) {
    const auto& same_scene = by_scene[column.scene_id];
    labels.push_back(same_scene.size() == 1
                         ? column.scene_id
                         : column.scene_id + " [" + distinguishing_parts(column, same_scene, rows) +
                               "]");
  }
  for (std::size_t i = 0; i < columns.size(); ++i) columns[i].label = labels[i];
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
  std::set<std::tuple<std::string, std::string, std::string>> seen;  // commit, series, scene
  std::set<std::string> commits;
  std::vector<HistoryRow> out;
  for (HistoryRow& row : rows) {
    const std::string key = commit_key(row);
    if (!seen.insert({key, row.series_id, row.scene_id}).second) continue;
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
    lines[at->second].scenes.emplace(row.series_id, row);
  }
  return lines;
}

std::vector<std::string> scene_ids(const std::vector<HistoryRow>& rows) {
  std::set<std::string> ids;
  for (const HistoryRow& row : rows) ids.insert(row.scene_id);
  return {ids.begin(), ids.end()};
}

std::vector<HistoryGroup> group_by_repository_and_adapter(const std::vector<HistoryRow>& rows) {
  std::vector<HistoryGroup> groups;
  std::vector<decltype(recency(HistoryRow{}))> newest;  // per group
  std::map<std::pair<std::string, std::string>, std::size_t> index;
  for (const HistoryRow& row : rows) {
    auto [at, fresh] = index.try_emplace({row.repository_key, row.adapter_name}, groups.size());
    if (fresh) {
      groups.push_back({row.repository_key, row.adapter_name, {}});
      newest.push_back(recency(row));
    }
    groups[at->second].rows.push_back(row);
    newest[at->second] = std::max(newest[at->second], recency(row));
  }
  std::vector<std::size_t> order(groups.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return newest[a] > newest[b]; });
  std::vector<HistoryGroup> sorted;
  for (const std::size_t i : order) sorted.push_back(std::move(groups[i]));
  return sorted;
}

std::vector<SeriesColumn> series_columns(const std::vector<HistoryRow>& rows) {
  std::map<std::string, SeriesColumn> by_id;
  for (const HistoryRow& row : rows) {
    by_id.try_emplace(row.series_id, SeriesColumn{row.series_id, row.scene_id, row.scene_id, row});
  }
  std::vector<SeriesColumn> columns;
  for (auto& [id, column] : by_id) columns.push_back(std::move(column));
  std::sort(columns.begin(), columns.end(), [](const SeriesColumn& a, const SeriesColumn& b) {
    return std::tie(a.scene_id, a.sample.suite, a.sample.scene_settings, a.sample.timing,
                    a.sample.baseline_sha256, a.sample.baseline_accel, a.series_id) <
           std::tie(b.scene_id, b.sample.suite, b.sample.scene_settings, b.sample.timing,
                    b.sample.baseline_sha256, b.sample.baseline_accel, b.series_id);
  });
  label_columns(columns, rows);
  return columns;
}

namespace {

// The values of a series, oldest first, with the commits they came from.
struct SeriesValues {
  std::vector<double> values;
  std::vector<std::string> short_shas;
};

SeriesValues series_values(const std::vector<CommitLine>& lines, const SeriesColumn& column,
                           std::optional<double> HistoryRow::*value) {
  SeriesValues out;
  for (auto line = lines.rbegin(); line != lines.rend(); ++line) {
    const auto found = line->scenes.find(column.series_id);
    if (found == line->scenes.end() || !(found->second.*value)) continue;
    out.values.push_back(*(found->second.*value));
    out.short_shas.push_back(found->second.short_sha);
  }
  return out;
}

std::string arrow_of(double change) {
  return change > kTrendFlatFraction ? "↑" : change < -kTrendFlatFraction ? "↓" : "→";
}

// Peaks that differ by less than a compare's noise floor (max(1 MiB, 2%)) draw flat: a
// sparkline scaled to a few KiB of page-level jitter would show a change that is none.
std::string memory_sparkline(const std::vector<double>& peaks_kib) {
  if (peaks_kib.empty()) return {};
  const auto [low, high] = std::minmax_element(peaks_kib.begin(), peaks_kib.end());
  if (*high - *low >= std::max(kMemoryNoiseFloorKib, kMemoryNoiseFraction * *high)) {
    return sparkline(peaks_kib);
  }
  return sparkline(std::vector<double>(peaks_kib.size(), *high));
}

void fill_memory_trend(SceneTrend& trend, const SeriesValues& peaks) {
  trend.peaks_kib = peaks.values;
  trend.memory_sparkline = memory_sparkline(peaks.values);
  if (peaks.values.empty()) return;
  trend.latest_peak_kib = peaks.values.back();
  if (peaks.values.size() < 2) return;
  trend.peak_change = *trend.latest_peak_kib / peaks.values[peaks.values.size() - 2] - 1.0;
  trend.previous_peak_short_sha = peaks.short_shas[peaks.short_shas.size() - 2];
  trend.memory_arrow = arrow_of(*trend.peak_change);
}

}  // namespace

SceneTrend scene_trend(const std::vector<CommitLine>& lines, const SeriesColumn& column) {
  SceneTrend trend;
  trend.series_id = column.series_id;
  trend.scene_id = column.scene_id;
  trend.label = column.label;
  fill_memory_trend(trend, series_values(lines, column, &HistoryRow::peak_memory_kib));
  const SeriesValues ratios = series_values(lines, column, &HistoryRow::ratio);
  trend.ratios = ratios.values;
  trend.sparkline = sparkline(trend.ratios);
  if (trend.ratios.empty()) return trend;
  trend.latest = trend.ratios.back();
  if (trend.ratios.size() < 2) return trend;
  const double previous = trend.ratios[trend.ratios.size() - 2];
  trend.change = *trend.latest / previous - 1.0;
  trend.previous_short_sha = ratios.short_shas[ratios.short_shas.size() - 2];
  trend.arrow = arrow_of(*trend.change);
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

#include "alert/history_alert.h"

#include <fmt/core.h>

#include <algorithm>
#include <map>

#include "core/error.h"
#include "gate/memory_gate.h"

namespace raygate {

namespace {

CommitRef commit_of(const HistoryRow& row) {
  return {row.sha, row.short_sha, row.subject, row.commit_time};
}

// The series' rows that have `value`, oldest first.
std::vector<HistoryRow> oldest_first(const std::vector<HistoryRow>& rows,
                                     const std::string& series_id,
                                     std::optional<double> HistoryRow::*value) {
  std::vector<HistoryRow> points;
  for (const HistoryRow& row : rows) {
    if (row.series_id == series_id && row.*value) points.push_back(row);
  }
  std::reverse(points.begin(), points.end());  // history() gives them newest first
  return points;
}

// The change points of `value` over `points` (oldest first), placed between their commits.
std::vector<SeriesChange> changes_of(const std::vector<HistoryRow>& points,
                                     std::optional<double> HistoryRow::*value,
                                     const EDivisiveOptions& detection) {
  std::vector<double> values;
  for (const HistoryRow& row : points) values.push_back(*(row.*value));
  std::vector<SeriesChange> changes;
  for (const ChangePoint& change : e_divisive(values, detection)) {
    changes.push_back({commit_of(points[change.index - 1]), commit_of(points[change.index]),
                       points.size() - change.index, change});
  }
  return changes;
}

// Peak memory: a step counts when it is over the limit and over the floor that page-level
// jitter never reaches (measure/memory_change.h), as a compare's memory verdict needs.
std::optional<MemoryTrack> judge_memory(const SeriesColumn& column,
                                        const std::vector<HistoryRow>& rows,
                                        const GatePolicy& policy,
                                        const EDivisiveOptions& detection) {
  const std::vector<HistoryRow> points =
      oldest_first(rows, column.series_id, &HistoryRow::peak_memory_kib);
  if (points.empty()) return std::nullopt;
  MemoryTrack track;
  track.points = points.size();
  track.limit = policy.for_scene(column.scene_id).max_memory_increase;
  track.changes = changes_of(points, &HistoryRow::peak_memory_kib, detection);
  if (track.changes.empty()) return track;
  const ChangePoint& newest = track.changes.back().change;
  if (newest.relative_change() > track.limit &&
      newest.mean_after - newest.mean_before > kMemoryNoiseFloorKib) {
    track.alert = track.changes.back();
  }
  return track;
}

SeriesJudgement judge_series(const SeriesColumn& column, const std::vector<HistoryRow>& rows,
                             const GatePolicy& policy, const EDivisiveOptions& detection) {
  SeriesJudgement judgement;
  judgement.column = column;
  judgement.limit = policy.for_scene(column.scene_id).max_slowdown;
  const std::vector<HistoryRow> points = oldest_first(rows, column.series_id, &HistoryRow::ratio);
  judgement.points = points.size();
  judgement.changes = changes_of(points, &HistoryRow::ratio, detection);
  if (!judgement.changes.empty() &&
      judgement.changes.back().change.relative_change() > judgement.limit) {
    judgement.alert = judgement.changes.back();
  }
  judgement.memory = judge_memory(column, rows, policy, detection);
  return judgement;
}

nlohmann::json commit_json(const CommitRef& commit) {
  return {{"sha", commit.sha},
          {"short_sha", commit.short_sha},
          {"subject", commit.subject},
          {"commit_time", commit.commit_time}};
}

nlohmann::json change_json(const SeriesChange& change) {
  return {{"last_before", commit_json(change.last_before)},
          {"first_after", commit_json(change.first_after)},
          {"commits_after", change.commits_after},
          {"mean_before", change.change.mean_before},
          {"mean_after", change.change.mean_after},
          {"relative_change", change.change.relative_change()},
          {"statistic", change.change.statistic},
          {"p_value", change.change.p_value}};
}

nlohmann::json changes_json(const std::vector<SeriesChange>& changes) {
  nlohmann::json out = nlohmann::json::array();
  for (const SeriesChange& change : changes) out.push_back(change_json(change));
  return out;
}

nlohmann::json memory_json(const std::optional<MemoryTrack>& memory) {
  if (!memory) return nullptr;
  return {{"points", memory->points},
          {"max_memory_increase", memory->limit},
          {"change_points", changes_json(memory->changes)},
          {"alert", memory->alert ? change_json(*memory->alert) : nlohmann::json(nullptr)}};
}

nlohmann::json series_json(const SeriesJudgement& s) {
  const nlohmann::json changes = changes_json(s.changes);
  const HistoryRow& parts = s.column.sample;
  return {{"series_id", s.column.series_id},
          {"scene", s.column.scene_id},
          {"label", s.column.label},
          {"repository", parts.repository_key},
          {"adapter", parts.adapter_name},
          {"suite", parts.suite},
          {"timing", parts.timing},
          {"points", s.points},
          {"max_slowdown", s.limit},
          {"change_points", changes},
          {"alert", s.alert ? change_json(*s.alert) : nlohmann::json(nullptr)},
          {"memory", memory_json(s.memory)}};
}

std::string range_text(const SeriesChange& c) {
  return fmt::format("{}..{} ({} \"{}\" .. {} \"{}\")", c.last_before.short_sha,
                     c.first_after.short_sha, c.last_before.short_sha, c.last_before.subject,
                     c.first_after.short_sha, c.first_after.subject);
}

std::string time_alert_line(const SeriesJudgement& s, const SeriesChange& c) {
  return fmt::format(
      "REGRESSED  {:<10} {:+.1f}% ({:.3f} -> {:.3f}, limit {:+.1f}%, p = {:.3f}) between {}; "
      "{} commits since\n",
      s.column.label, 100 * c.change.relative_change(), c.change.mean_before, c.change.mean_after,
      100 * s.limit, c.change.p_value, range_text(c), c.commits_after);
}

std::string memory_alert_line(const SeriesJudgement& s, const SeriesChange& c) {
  return fmt::format(
      "REGRESSED  {:<10} memory {:+.1f}% ({} -> {}, limit {:+.0f}%, p = {:.3f}) between {}; "
      "{} commits since\n",
      s.column.label, 100 * c.change.relative_change(), memory_text(c.change.mean_before),
      memory_text(c.change.mean_after), 100 * s.memory->limit, c.change.p_value, range_text(c),
      c.commits_after);
}

}  // namespace

std::size_t AlertJudgement::alerts() const {
  return static_cast<std::size_t>(std::count_if(
      series.begin(), series.end(), [](const SeriesJudgement& s) { return s.in_alert(); }));
}

int AlertJudgement::exit_code() const {
  return alerts() > 0 && action == AlertAction::fail ? 1 : 0;
}

AlertJudgement judge_history(const std::vector<HistoryRow>& rows, const GatePolicy& policy,
                             const EDivisiveOptions& detection, AlertAction action) {
  AlertJudgement judgement;
  judgement.action = action;
  judgement.points_to_find_a_change = 2 * detection.min_segment;
  for (const SeriesColumn& column : series_columns(rows)) {
    judgement.series.push_back(judge_series(column, rows, policy, detection));
  }
  return judgement;
}

std::string_view to_string(AlertAction action) {
  return action == AlertAction::fail ? "fail" : "annotate";
}

AlertAction parse_alert_action(std::string_view text) {
  for (const AlertAction action : {AlertAction::fail, AlertAction::annotate}) {
    if (to_string(action) == text) return action;
  }
  throw UsageError(fmt::format("alert action '{}': expected fail or annotate", text));
}

nlohmann::json alert_json(const AlertJudgement& judgement, const EDivisiveOptions& detection) {
  nlohmann::json series = nlohmann::json::array();
  for (const SeriesJudgement& s : judgement.series) series.push_back(series_json(s));
  return {{"method", "e-divisive means"},
          {"min_segment", detection.min_segment},
          {"permutations", detection.permutations},
          {"significance", detection.significance},
          {"seed", detection.seed},
          {"action", std::string(to_string(judgement.action))},
          {"alerts", judgement.alerts()},
          {"exit_code", judgement.exit_code()},
          {"series", series}};
}

std::string alert_text(const AlertJudgement& judgement) {
  std::string out;
  for (const SeriesJudgement& s : judgement.series) {
    if (s.alert) out += time_alert_line(s, *s.alert);
    if (s.memory && s.memory->alert) out += memory_alert_line(s, *s.memory->alert);
  }
  const std::size_t alerts = judgement.alerts();
  std::size_t changes = 0;
  for (const SeriesJudgement& s : judgement.series) {
    changes += s.changes.size() + (s.memory ? s.memory->changes.size() : 0);
  }
  std::size_t too_short = 0;
  for (const SeriesJudgement& s : judgement.series) {
    too_short += s.points < judgement.points_to_find_a_change ? 1 : 0;
  }
  out += fmt::format(
      "alert: {}: {} series, {} in alert, {} change points{}{}\n",
      alerts == 0                             ? "OK"
      : judgement.action == AlertAction::fail ? "FAIL"
                                              : "ANNOTATE",
      judgement.series.size(), alerts, changes,
      alerts > 0 && judgement.action == AlertAction::annotate ? " (annotate: not failing)" : "",
      too_short == 0 ? ""
                     : fmt::format("; {} too short to show a change (fewer than {} points)",
                                   too_short, judgement.points_to_find_a_change));
  return out;
}

}  // namespace raygate

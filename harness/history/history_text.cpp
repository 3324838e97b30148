// The history table for the terminal and its JSON form.
#include <fmt/core.h>

#include <algorithm>
#include <optional>

#include "compare/image_verdict.h"
#include "core/domain.h"
#include "gate/memory_gate.h"
#include "history/history_view.h"
#include "report/report_model.h"

namespace raygate {

namespace {

constexpr std::size_t kSubjectWidth = 32;
constexpr std::size_t kRatioWidth = 12;
constexpr std::size_t kImageWidth = 13;  // "inconclusive" and a space
constexpr std::size_t kPeakWidth = 9;    // "123.4 MiB"

// Table rows are padded column by column; the last column's padding is not wanted.
std::string trimmed_line(std::string line) {
  while (!line.empty() && line.back() == ' ') line.pop_back();
  return line + "\n";
}

bool is_continuation_byte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

std::size_t code_points(const std::string& text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return !is_continuation_byte(c); }));
}

std::string date_of(const HistoryRow& row) {
  const std::string& when = row.commit_time.empty() ? row.measured_at : row.commit_time;
  return when.substr(0, 10);
}

std::string ratio_cell(const HistoryRow& row) {
  if (!row.ratio) {
    return parse_scene_status(row.status) == SceneStatus::failed ? row.status : std::string("-");
  }
  if (!row.ratio_lower || !row.ratio_upper) return fmt::format("{:.3f}", *row.ratio);
  const double half_width = (*row.ratio_upper - *row.ratio_lower) / 2.0 / *row.ratio;
  return fmt::format("{:.3f} ±{:.1f}%", *row.ratio, half_width * 100.0);
}

// The stored word in the reports' words ("no golden", not "missing").
std::string image_cell(const HistoryRow& row) {
  if (row.image_verdict.empty()) return "-";
  const std::optional<ImageVerdict> verdict = parse_image_verdict(row.image_verdict);
  const std::string words = verdict ? report::image_verdict_text(*verdict) : row.image_verdict;
  if (!row.image_max_error) return words;
  const std::string error =
      *row.image_max_error == 0.0 ? "0" : fmt::format("{:.4f}", *row.image_max_error);
  return verdict == ImageVerdict::pass ? error : error + " " + words;
}

// The tracer's own peak memory; a compare's head row adds a verdict that is not UNCHANGED.
std::string peak_cell(const HistoryRow& row) {
  if (!row.peak_memory_kib) return "-";
  std::string cell = memory_text(*row.peak_memory_kib);
  const std::optional<ChangeVerdict> verdict = change_verdict_named(row.memory_verdict);
  if (verdict && *verdict != ChangeVerdict::unchanged) {
    cell += " " + row.memory_verdict;
  }
  return cell;
}

bool any_incomplete(const CommitLine& line) {
  return std::any_of(line.scenes.begin(), line.scenes.end(),
                     [](const auto& scene) { return !scene.second.complete; });
}

std::size_t sha_width(const HistoryTable& table) {
  std::size_t width = 7;
  for (const CommitLine& line : table.lines) {
    width = std::max(width, code_points(line.commit.short_sha) + 1);
  }
  return width;
}

std::string header_lines(const HistoryTable& table, std::size_t sha_w) {
  std::string first = pad_right("date", 10) + "  " + pad_right("commit", sha_w) + "  " +
                      pad_right("subject", kSubjectWidth);
  std::string second(first.size(), ' ');
  for (const SeriesColumn& column : table.columns) {
    first += "  " + pad_right(column.label, kRatioWidth + 2 + kImageWidth + 2 + kPeakWidth);
    second += "  " + pad_right("ratio", kRatioWidth) + "  " + pad_right("image", kImageWidth) +
              "  " + pad_right("peak", kPeakWidth);
  }
  return trimmed_line(first) + trimmed_line(second);
}

std::string commit_row(const HistoryTable& table, const CommitLine& line, std::size_t sha_w) {
  const HistoryRow& c = line.commit;
  const std::string sha = c.short_sha + (any_incomplete(line) ? "*" : "");
  std::string out = pad_right(date_of(c), 10) + "  " + pad_right(sha, sha_w) + "  " +
                    pad_right(truncate_text(c.subject, kSubjectWidth), kSubjectWidth);
  for (const SeriesColumn& column : table.columns) {
    const auto found = line.scenes.find(column.series_id);
    const bool has = found != line.scenes.end();
    out += "  " + pad_right(has ? ratio_cell(found->second) : "", kRatioWidth) + "  " +
           pad_right(has ? image_cell(found->second) : "", kImageWidth) + "  " +
           pad_right(has ? peak_cell(found->second) : "", kPeakWidth);
  }
  return trimmed_line(out);
}

std::string trend_line(const SceneTrend& trend, std::size_t scene_w, std::size_t spark_w) {
  std::string out =
      "  " + pad_right(trend.label, scene_w) + "  " + pad_right(trend.sparkline, spark_w) + "  ";
  if (!trend.latest) return out + "no ratio measured\n";
  out += fmt::format("{:.3f}", *trend.latest);
  if (!trend.change) return out + "  first measurement\n";
  return out + fmt::format("  {:+.1f}% {} vs {}\n", *trend.change * 100.0, trend.arrow,
                           trend.previous_short_sha);
}

std::string memory_trend_line(const SceneTrend& trend, std::size_t scene_w, std::size_t spark_w) {
  std::string out = "  " + pad_right(trend.label, scene_w) + "  " +
                    pad_right(trend.memory_sparkline, spark_w) + "  ";
  if (!trend.latest_peak_kib) return out + "no peak measured\n";
  out += memory_text(*trend.latest_peak_kib);
  if (!trend.peak_change) return out + "  first measurement\n";
  return out + fmt::format("  {:+.1f}% {} vs {}\n", *trend.peak_change * 100.0, trend.memory_arrow,
                           trend.previous_peak_short_sha);
}

// Only when some series has peaks: stores from before raygate-meter have none.
std::string memory_trend_section(const HistoryTable& table) {
  std::size_t scene_w = 5;
  std::size_t spark_w = 1;
  bool any = false;
  for (const SceneTrend& t : table.trends) {
    scene_w = std::max(scene_w, code_points(t.label));
    spark_w = std::max(spark_w, code_points(t.memory_sparkline));
    any = any || t.latest_peak_kib.has_value();
  }
  if (!any) return "";
  std::string out = "memory (peak resident, the tracer's own; oldest -> newest):\n";
  for (const SceneTrend& t : table.trends) out += memory_trend_line(t, scene_w, spark_w);
  return out;
}

std::string trend_section(const HistoryTable& table) {
  std::size_t scene_w = 5;
  std::size_t spark_w = 1;
  for (const SceneTrend& t : table.trends) {
    scene_w = std::max(scene_w, code_points(t.label));
    spark_w = std::max(spark_w, code_points(t.sparkline));
  }
  std::string out = "trend (oldest -> newest; a ratio going up is the tracer getting slower):\n";
  for (const SceneTrend& t : table.trends) out += trend_line(t, scene_w, spark_w);
  return out;
}

std::string table_text(const HistoryTable& table) {
  const std::size_t sha_w = sha_width(table);
  std::string out = fmt::format("repository {}, adapter {}: {} commit{}, newest first\n\n",
                                short_repository(table.repository_key), table.adapter_name,
                                table.lines.size(), table.lines.size() == 1 ? "" : "s");
  out += header_lines(table, sha_w);
  for (const CommitLine& line : table.lines) out += commit_row(table, line, sha_w);
  if (std::any_of(table.lines.begin(), table.lines.end(), any_incomplete)) {
    out += "* from a results document that did not finish every scene\n";
  }
  out += "\n";
  out += trend_section(table);
  out += memory_trend_section(table);
  if (table.baseline_versions > 1) {
    out += fmt::format(
        "\nnote: these commits were measured with {} different baseline sources; each is its own "
        "series, and ratios compare only within one\n",
        table.baseline_versions);
  }
  return out;
}

nlohmann::json optional_number(const std::optional<double>& value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

nlohmann::json scene_json(const HistoryRow& row) {
  return {{"status", row.status},
          {"normalized_ratio", optional_number(row.ratio)},
          {"ratio_interval", {optional_number(row.ratio_lower), optional_number(row.ratio_upper)}},
          {"baseline_median_seconds", optional_number(row.baseline_median_seconds)},
          {"image",
           {{"verdict", row.image_verdict},
            {"max_error", optional_number(row.image_max_error)},
            {"rms_error", optional_number(row.image_rms_error)}}},
          {"memory",
           {{"peak_kib", optional_number(row.peak_memory_kib)},
            {"change", optional_number(row.memory_change)},
            {"verdict", row.memory_verdict}}},
          {"machine", {{"hostname", row.machine_hostname}, {"cpu_model", row.machine_cpu_model}}},
          {"baseline_sha256", row.baseline_sha256},
          {"document_id", row.document_id},
          {"complete", row.complete},
          {"measured_at", row.measured_at},
          {"stored_at", row.stored_at}};
}

nlohmann::json commit_json(const HistoryTable& table, const CommitLine& line) {
  const HistoryRow& c = line.commit;
  nlohmann::json scenes = nlohmann::json::object();
  for (const SeriesColumn& column : table.columns) {
    const auto found = line.scenes.find(column.series_id);
    if (found != line.scenes.end()) scenes[column.label] = scene_json(found->second);
  }
  return {{"sha", c.sha},       {"short_sha", c.short_sha},     {"subject", c.subject},
          {"branch", c.branch}, {"commit_time", c.commit_time}, {"dirty", c.dirty},
          {"scenes", scenes}};
}

nlohmann::json trend_json(const SceneTrend& t) {
  return {{"series", t.series_id},
          {"ratios", t.ratios},
          {"latest", optional_number(t.latest)},
          {"change_vs_previous", optional_number(t.change)},
          {"previous_short_sha", t.previous_short_sha},
          {"sparkline", t.sparkline},
          {"peaks_kib", t.peaks_kib},
          {"latest_peak_kib", optional_number(t.latest_peak_kib)},
          {"peak_change_vs_previous", optional_number(t.peak_change)},
          {"previous_peak_short_sha", t.previous_peak_short_sha},
          {"memory_sparkline", t.memory_sparkline}};
}

nlohmann::json series_json(const SeriesColumn& column) {
  const HistoryRow& r = column.sample;
  return {{"id", column.series_id},
          {"scene", column.scene_id},
          {"suite", r.suite},
          {"scene_settings", r.scene_settings},
          {"timing", r.timing},
          {"baseline_sha256", r.baseline_sha256},
          {"baseline_accel", r.baseline_accel}};
}

nlohmann::json table_json(const HistoryTable& table) {
  nlohmann::json commits = nlohmann::json::array();
  for (const CommitLine& line : table.lines) commits.push_back(commit_json(table, line));
  nlohmann::json series = nlohmann::json::object();
  for (const SeriesColumn& column : table.columns) series[column.label] = series_json(column);
  nlohmann::json trends = nlohmann::json::object();
  for (const SceneTrend& t : table.trends) trends[t.label] = trend_json(t);
  return {{"repository", table.repository_key},
          {"adapter", table.adapter_name},
          {"commits", commits},
          {"series", series},
          {"trends", trends},
          {"baseline_versions", table.baseline_versions}};
}

nlohmann::json drift_json(const std::optional<MachineDrift>& drift) {
  if (!drift) return nullptr;
  return {{"hostname", drift->hostname},
          {"cpu_model", drift->cpu_model},
          {"document_id", drift->document_id},
          {"scenes_compared", drift->scenes_compared},
          {"scenes_drifted", drift->scenes_drifted},
          {"median_baseline_change", drift->median_baseline_change},
          {"machine_got", drift->faster() ? "faster" : "slower"},
          {"note", describe_drift(*drift)}};
}

}  // namespace

std::string history_table(const HistoryView& view) {
  const std::string scope =
      fmt::format("role {}{}", view.role, view.branch.empty() ? "" : ", branch " + view.branch);
  if (view.tables.empty()) return fmt::format("no results in {} match ({})\n", view.store, scope);
  std::string out = fmt::format(
      "history from {} ({}), one table per repository and adapter\n"
      "ratio = time(tracer) / time(baseline) with its 95% CI half-width; image = max error "
      "against the golden; peak = peak resident memory, the tracer's own\n",
      view.store, scope);
  for (const HistoryTable& table : view.tables) {
    out += "\n";
    out += table_text(table);
  }
  if (view.drift) out += fmt::format("\n{}\n", describe_drift(*view.drift));
  return out;
}

nlohmann::json history_json(const HistoryView& view) {
  nlohmann::json tables = nlohmann::json::array();
  for (const HistoryTable& table : view.tables) tables.push_back(table_json(table));
  return {{"store", view.store},
          {"role", view.role},
          {"branch", view.branch},
          {"tables", tables},
          {"machine_drift", drift_json(view.drift)}};
}

std::string pad_right(const std::string& text, std::size_t width) {
  const std::size_t length = code_points(text);
  return length >= width ? text : text + std::string(width - length, ' ');
}

std::string truncate_text(const std::string& text, std::size_t max_code_points) {
  if (code_points(text) <= max_code_points || max_code_points == 0) return text;
  std::size_t kept = 0;
  std::size_t end = 0;
  while (end < text.size()) {
    if (!is_continuation_byte(text[end]) && kept++ == max_code_points - 1) break;
    ++end;
  }
  return text.substr(0, end) + "…";
}

}  // namespace raygate

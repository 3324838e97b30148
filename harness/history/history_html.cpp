// `raygate history --html`: one self-contained page (inline CSS and SVG, no script, no network)
// with the normalized ratio per series over commits. The plot and the style are the HTML
// report's own (report/html_parts.h), so a trend reads the same on both pages.
#include <fmt/core.h>

#include <optional>
#include <vector>

#include "history/history_view.h"
#include "report/html_parts.h"

namespace raygate {

namespace {

using report::html::escape;  // one HTML escaping for every page raygate writes

// The series' commits that have `value`, oldest first, as points of a trend plot.
TrendSeries trend_series(const HistoryTable& table, const SeriesColumn& column,
                         std::optional<double> HistoryRow::*value,
                         TrendPoint (*point_of)(const HistoryRow&)) {
  TrendSeries series{column.label, {}};
  for (auto line = table.lines.rbegin(); line != table.lines.rend(); ++line) {
    const auto found = line->scenes.find(column.series_id);
    if (found != line->scenes.end() && found->second.*value) {
      series.points.push_back(point_of(found->second));
    }
  }
  return series;
}

// One plot with its caption, or what is missing.
std::string figure(const TrendSeries& series, report::html::TrendQuantity quantity,
                   const char* caption, const char* missing) {
  if (series.points.empty()) return fmt::format("<p>{}</p>\n", missing);
  return fmt::format("<figure><figcaption>{}</figcaption>{}</figure>\n", caption,
                     report::html::trend_svg(series, {}, quantity));
}

// The ratio's trend and, beside it, the peak memory's (issue 27) when the series has peaks.
std::string series_section(const HistoryTable& table, const SeriesColumn& column) {
  using report::html::TrendQuantity;
  const TrendSeries ratios = trend_series(table, column, &HistoryRow::ratio, trend_point);
  const TrendSeries peaks =
      trend_series(table, column, &HistoryRow::peak_memory_kib, memory_trend_point);
  std::string out = "<section class=\"card\">\n<h3>" + escape(column.label) + "</h3>\n";
  out += "<div class=\"trend-pair\">\n";
  out += figure(ratios, TrendQuantity::normalized_ratio, "normalized ratio (lower is faster)",
                "no normalized ratio measured");
  if (!peaks.points.empty()) {
    out += figure(peaks, TrendQuantity::peak_memory_mib,
                  "peak memory, MiB (the tracer's own; red: memory REGRESSED)", "");
  }
  return out + "</div>\n</section>\n";
}

std::string commit_table(const HistoryTable& table) {
  std::string out =
      "<table>\n<tr><th>date</th><th>commit</th><th>subject</th><th>branch</th></tr>\n";
  for (const CommitLine& line : table.lines) {
    const HistoryRow& c = line.commit;
    out += fmt::format("<tr><td>{}</td><td><code>{}</code></td><td>{}</td><td>{}</td></tr>\n",
                       escape(c.commit_time.substr(0, 10)), escape(c.short_sha), escape(c.subject),
                       escape(c.branch));
  }
  return out + "</table>\n";
}

std::string table_section(const HistoryTable& table) {
  std::string out =
      fmt::format("<h2>repository <code>{}</code>, adapter {}</h2>\n",
                  escape(short_repository(table.repository_key)), escape(table.adapter_name));
  for (const SeriesColumn& column : table.columns) out += series_section(table, column);
  return out + "<h3>commits, newest first</h3>\n" + commit_table(table);
}

}  // namespace

std::string history_html(const HistoryView& view) {
  std::string body = fmt::format(
      "<h1>raygate history</h1>\n<p>From <code>{}</code> (role {}{}), one part per repository "
      "and adapter, one plot per series. The normalized ratio is time(tracer) / time(baseline); "
      "lower is faster. The band is its 95% CI; hover a point for the commit; a red point's "
      "image failed its check. Beside it, where measured, the tracer's own peak resident memory "
      "(the median over the commit's rounds).</p>\n",
      escape(view.store), escape(view.role),
      view.branch.empty() ? "" : ", branch " + escape(view.branch));
  if (view.drift) {
    body += "<p class=\"note\">" + escape(describe_drift(*view.drift)) + "</p>\n";
  }
  for (const HistoryTable& table : view.tables) body += table_section(table);
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<title>raygate history</title>\n<style>" +
         std::string(report::html::page_style()) +
         "</style>\n</head>\n<body>\n<div class=\"page\">\n" + body + "</div>\n</body>\n</html>\n";
}

}  // namespace raygate

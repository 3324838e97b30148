// `raygate history --html`: one self-contained page (inline CSS and SVG, no script, no network)
// with a plot of the normalized ratio per scene over commits, its 95% CI as a band, and a hover
// title on each point with the commit and the numbers.
#include <fmt/core.h>

#include <algorithm>
#include <vector>

#include "report/html_parts.h"
#include "cli/history_view.h"

namespace raygate::cli {

namespace {

constexpr double kWidth = 760;
constexpr double kHeight = 260;
constexpr double kLeft = 60;
constexpr double kRight = 16;
constexpr double kTop = 14;
constexpr double kBottom = 40;
constexpr double kInset = 28;  // first and last commit this far inside the axes

using report::html::escape;  // one HTML escaping for every page raygate writes

struct Point {
  std::size_t commit = 0;  // index oldest first
  const HistoryRow* row = nullptr;
};

struct Scale {
  double low = 0;
  double high = 1;
  std::size_t commits = 1;

  double x(std::size_t index) const {
    const double plot = kWidth - kLeft - kRight - 2 * kInset;
    if (commits < 2) return kLeft + kInset + plot / 2;
    return kLeft + kInset + plot * static_cast<double>(index) / static_cast<double>(commits - 1);
  }
  double y(double value) const {
    const double plot = kHeight - kTop - kBottom;
    return kTop + plot * (high - value) / (high - low);
  }
};

std::vector<Point> scene_points(const std::vector<CommitLine>& oldest_first,
                                const std::string& series_id) {
  std::vector<Point> points;
  for (std::size_t i = 0; i < oldest_first.size(); ++i) {
    const auto found = oldest_first[i].scenes.find(series_id);
    if (found != oldest_first[i].scenes.end() && found->second.ratio) {
      points.push_back({i, &found->second});
    }
  }
  return points;
}

Scale scale_for(const std::vector<Point>& points, std::size_t commits) {
  Scale s;
  s.commits = commits;
  s.low = s.high = *points.front().row->ratio;
  for (const Point& p : points) {
    s.low = std::min({s.low, *p.row->ratio, p.row->ratio_lower.value_or(*p.row->ratio)});
    s.high = std::max({s.high, *p.row->ratio, p.row->ratio_upper.value_or(*p.row->ratio)});
  }
  const double margin = std::max((s.high - s.low) * 0.08, s.high * 0.01);
  s.low = std::max(0.0, s.low - margin);
  s.high += margin;
  return s;
}

std::string axes(const Scale& s, const std::vector<CommitLine>& oldest_first) {
  std::string out = fmt::format(
      "<line class=\"axis\" x1=\"{0}\" y1=\"{1}\" x2=\"{0}\" y2=\"{2}\"/>"
      "<line class=\"axis\" x1=\"{0}\" y1=\"{2}\" x2=\"{3}\" y2=\"{2}\"/>\n",
      kLeft, kTop, kHeight - kBottom, kWidth - kRight);
  for (int i = 0; i <= 4; ++i) {
    const double value = s.low + (s.high - s.low) * i / 4.0;
    out += fmt::format(
        "<line class=\"grid\" x1=\"{0}\" y1=\"{1:.1f}\" x2=\"{2}\" y2=\"{1:.1f}\"/>"
        "<text x=\"{3}\" y=\"{4:.1f}\" text-anchor=\"end\">{5:.3f}</text>\n",
        kLeft, s.y(value), kWidth - kRight, kLeft - 6, s.y(value) + 4, value);
  }
  const std::size_t step = std::max<std::size_t>(1, (oldest_first.size() + 9) / 10);
  for (std::size_t i = 0; i < oldest_first.size(); i += step) {
    out += fmt::format("<text x=\"{:.1f}\" y=\"{}\" text-anchor=\"middle\">{}</text>\n", s.x(i),
                       kHeight - kBottom + 16, escape(oldest_first[i].commit.short_sha));
  }
  return out;
}

std::string band(const Scale& s, const std::vector<Point>& points) {
  std::string upper;
  std::string lower;
  for (const Point& p : points) {
    if (!p.row->ratio_lower || !p.row->ratio_upper) continue;
    upper += fmt::format("{:.1f},{:.1f} ", s.x(p.commit), s.y(*p.row->ratio_upper));
    lower.insert(0, fmt::format("{:.1f},{:.1f} ", s.x(p.commit), s.y(*p.row->ratio_lower)));
  }
  if (upper.empty()) return {};
  return "<polygon class=\"ci\" points=\"" + upper + lower + "\"/>\n";
}

std::string point_title(const HistoryRow& row) {
  std::string title = fmt::format("{} {}: ratio {:.4f}", row.short_sha, row.subject, *row.ratio);
  if (row.ratio_lower && row.ratio_upper) {
    title += fmt::format(" [{:.4f}, {:.4f}]", *row.ratio_lower, *row.ratio_upper);
  }
  if (row.image_max_error) {
    title += fmt::format("; image max error {:.4f} ({})", *row.image_max_error, row.image_verdict);
  }
  return escape(title);
}

std::string line_and_points(const Scale& s, const std::vector<Point>& points) {
  std::string line;
  std::string dots;
  for (const Point& p : points) {
    line += fmt::format("{:.1f},{:.1f} ", s.x(p.commit), s.y(*p.row->ratio));
    const char* css = p.row->image_verdict == "fail" ? "point fail" : "point";
    dots += fmt::format(
        "<circle class=\"{}\" cx=\"{:.1f}\" cy=\"{:.1f}\" r=\"4\"><title>{}"
        "</title></circle>\n",
        css, s.x(p.commit), s.y(*p.row->ratio), point_title(*p.row));
  }
  return "<polyline class=\"ratio\" points=\"" + line + "\"/>\n" + dots;
}

std::string scene_section(const std::vector<CommitLine>& oldest_first,
                          const SeriesColumn& column) {
  const std::vector<Point> points = scene_points(oldest_first, column.series_id);
  const std::string& scene = column.label;
  std::string out = "<section>\n<h3>" + escape(scene) + "</h3>\n";
  if (points.empty()) return out + "<p>no normalized ratio measured</p>\n</section>\n";
  const Scale s = scale_for(points, oldest_first.size());
  out += fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {} {}\" "
      "width=\"{}\" height=\"{}\" role=\"img\" aria-label=\"normalized ratio of "
      "{} over commits\">\n",
      kWidth, kHeight, kWidth, kHeight, escape(scene));
  out += axes(s, oldest_first) + band(s, points) + line_and_points(s, points);
  return out + "</svg>\n</section>\n";
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

const char* const kStyle = R"css(
body { font-family: system-ui, sans-serif; margin: 2em; color: #222; max-width: 820px; }
h1 { font-size: 1.4em; } h2 { font-size: 1.2em; margin-top: 1.5em; }
h3 { font-size: 1.05em; margin-bottom: 0.2em; }
svg text { font-size: 11px; fill: #444; }
.axis { stroke: #444; } .grid { stroke: #ddd; }
.ci { fill: #4a7bd0; fill-opacity: 0.18; stroke: none; }
.ratio { fill: none; stroke: #2a5bb0; stroke-width: 2; }
.point { fill: #2a5bb0; } .point.fail { fill: #c0392b; }
.note { background: #fff6d5; padding: 0.6em; border-left: 4px solid #e0b000; }
table { border-collapse: collapse; } td, th { padding: 2px 10px; text-align: left; }
)css";

std::string table_section(const HistoryTable& table) {
  const std::vector<CommitLine> oldest_first(table.lines.rbegin(), table.lines.rend());
  std::string out = fmt::format("<h2>repository <code>{}</code>, adapter {}</h2>\n",
                                escape(short_repository(table.repository_key)),
                                escape(table.adapter_name));
  for (const SeriesColumn& column : table.columns) out += scene_section(oldest_first, column);
  return out + "<h3>commits, newest first</h3>\n" + commit_table(table);
}

}  // namespace

std::string history_html(const HistoryView& view) {
  std::string body = fmt::format(
      "<h1>raygate history</h1>\n<p>From <code>{}</code> (role {}{}), one part per repository "
      "and adapter, one plot per series. The normalized ratio is time(tracer) / time(baseline); "
      "lower is faster. The band is its 95% CI; hover a point for the commit.</p>\n",
      escape(view.store), escape(view.role),
      view.branch.empty() ? "" : ", branch " + escape(view.branch));
  if (view.drift) body += "<p class=\"note\">" + escape(describe_drift(*view.drift)) + "</p>\n";
  for (const HistoryTable& table : view.tables) body += table_section(table);
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
         "<title>raygate history</title>\n<style>" +
         std::string(kStyle) + "</style>\n</head>\n<body>\n" + body + "</body>\n</html>\n";
}

}  // namespace raygate::cli

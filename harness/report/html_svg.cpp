// Inline SVG plots of the HTML report: interval bars for the ratios' and the change's
// confidence intervals, and the trend of a scene's normalized ratio over commits. Plain SVG
// elements styled by the page's CSS classes, so the page needs no plotting library.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "report/html_parts.h"

namespace raygate::report::html {
namespace {

// A linear map from data to pixels.
struct Scale {
  double lo = 0.0, hi = 1.0;  // data
  double a = 0.0, b = 1.0;    // pixels (b < a for a y axis)
  double operator()(double v) const { return a + (v - lo) / (hi - lo) * (b - a); }
};

// The smallest [lo, hi] holding every item's value and interval (items with .lower and
// .upper; `value` the member of the point estimate). Not empty.
template <typename Item>
std::pair<double, double> interval_span(const std::vector<Item>& items, double Item::*value) {
  double lo = items.front().lower, hi = items.front().upper;
  for (const Item& item : items) {
    lo = std::min({lo, item.lower, item.*value});
    hi = std::max({hi, item.upper, item.*value});
  }
  return {lo, hi};
}

// The data range of [lo, hi] with a margin, never empty.
std::pair<double, double> padded_range(std::pair<double, double> span, double margin) {
  const auto [lo, hi] = span;
  if (!(hi > lo)) {
    const double half = std::max(std::abs(lo) * 0.05, 1e-3);
    return {lo - half, hi + half};
  }
  const double pad = (hi - lo) * margin;
  return {lo - pad, hi + pad};
}

double nice_step(double range, int target) {
  const double raw = range / std::max(target, 1);
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (raw <= m * power) return m * power;
  }
  return 10.0 * power;
}

std::vector<double> ticks(double lo, double hi, int target) {
  const double step = nice_step(hi - lo, target);
  std::vector<double> out;
  for (double t = std::ceil(lo / step) * step; t <= hi + step * 1e-9; t += step) {
    out.push_back(std::abs(t) < step * 1e-9 ? 0.0 : t);
  }
  return out;
}

// Enough decimals to tell the ticks apart: 0.025 needs 3, 0.05 needs 2, 5 needs 0.
int decimals_for(double lo, double hi, int target) {
  const double step = nice_step(hi - lo, target);
  for (int decimals = 0; decimals < 6; ++decimals) {
    const double scaled = step * std::pow(10.0, decimals);
    if (std::abs(scaled - std::round(scaled)) < 1e-6 * scaled) return decimals;
  }
  return 6;
}

std::string svg_open(int width, int height, const std::string& css_class,
                     const std::string& label) {
  return fmt::format(
      R"(<svg class="{}" viewBox="0 0 {} {}" width="{}" height="{}" role="img" aria-label="{}">)",
      css_class, width, height, width, height, escape(label));
}

std::string text(double x, double y, const std::string& css_class, const std::string& content,
                 const char* anchor_pos = "start") {
  return fmt::format(R"(<text x="{:.1f}" y="{:.1f}" class="{}" text-anchor="{}">{}</text>)", x, y,
                     css_class, anchor_pos, escape(content));
}

std::string x_axis(const Scale& x, double y, int target, int decimals, const std::string& suffix,
                   double percent_factor) {
  std::string out = fmt::format(
      R"(<line class="svg-axis" x1="{:.1f}" x2="{:.1f}" y1="{}" y2="{}"/>)", x.a, x.b, y, y);
  for (const double t : ticks(x.lo, x.hi, target)) {
    out += fmt::format(R"(<line class="svg-axis" x1="{0:.1f}" x2="{0:.1f}" y1="{1}" y2="{2}"/>)",
                       x(t), y, y + 4);
    const std::string sign = suffix == "%" && t > 0 ? "+" : "";
    out += text(x(t), y + 15, "svg-tick",
                fmt::format("{}{:.{}f}{}", sign, t * percent_factor, decimals, suffix), "middle");
  }
  return out;
}

// A CI as a bar with end caps and the estimate as a dot.
std::string interval_mark(const Scale& x, double y, double value, double lower, double upper,
                          const std::string& css_class, const std::string& tooltip) {
  return fmt::format(R"(<g class="mark {0}"><title>{1}</title>)"
                     R"(<line class="ci" x1="{2:.1f}" x2="{3:.1f}" y1="{4}" y2="{4}"/>)"
                     R"(<line class="cap" x1="{2:.1f}" x2="{2:.1f}" y1="{5}" y2="{6}"/>)"
                     R"(<line class="cap" x1="{3:.1f}" x2="{3:.1f}" y1="{5}" y2="{6}"/>)"
                     R"(<circle cx="{7:.1f}" cy="{4}" r="4.5"/></g>)",
                     css_class, escape(tooltip), x(lower), x(upper), y, y - 5, y + 5, x(value));
}

}  // namespace

std::string ratio_bars_svg(const std::vector<IntervalRow>& rows) {
  if (rows.empty()) return "";
  const auto [dlo, dhi] = padded_range(interval_span(rows, &IntervalRow::value), 0.15);
  const int width = 440, row_height = 26, top = 8;
  const int height = top + static_cast<int>(rows.size()) * row_height + 24;
  const Scale x{dlo, dhi, 58.0, 290.0};
  std::string out = svg_open(width, height, "plot ratio-plot", "normalized ratio with 95% CI");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const IntervalRow& r = rows[i];
    const double y = top + row_height * (static_cast<double>(i) + 0.5);
    const std::string numbers = fmt::format("{:.3f} [{:.3f}, {:.3f}]", r.value, r.lower, r.upper);
    out += text(50, y + 4, "svg-label", r.label, "end");
    out += interval_mark(x, y, r.value, r.lower, r.upper, r.css_class, r.label + " " + numbers);
    out += text(302, y + 4, "svg-value", numbers);
  }
  out += x_axis(x, top + static_cast<double>(rows.size()) * row_height + 2, 4,
                decimals_for(dlo, dhi, 4), "", 1.0);
  return out + "</svg>";
}

std::string change_bar_svg(const ChangeCell& cell, double threshold, const std::string& css_class) {
  const Interval interval = cell.interval.value_or(Interval{cell.change, cell.change});
  const double change = cell.change;
  const double reach = std::max({2.0 * threshold, std::abs(interval.lower),
                                 std::abs(interval.upper), std::abs(change), 0.01}) *
                       1.15;
  const Scale x{-reach, reach, 58.0, 290.0};
  const double y = 22;
  const std::string title =
      "change head vs base" + (cell.interval_name.empty() ? "" : " with its " + cell.interval_name);
  std::string out = svg_open(440, 62, "plot change-plot", title);
  out += fmt::format(R"(<rect class="band" x="{:.1f}" y="8" width="{:.1f}" height="28"/>)",
                     x(-threshold), x(threshold) - x(-threshold));
  out += fmt::format(R"(<line class="zero" x1="{0:.1f}" x2="{0:.1f}" y1="6" y2="38"/>)", x(0.0));
  out += text(50, y + 4, "svg-label", "change", "end");
  out += interval_mark(x, y, change, interval.lower, interval.upper, css_class,
                       "head vs base " + cell.text);
  out += text(302, y + 4, "svg-value", signed_percent(change, cell.exact ? 3 : 1));
  std::string note = cell.exact
                         ? "exact (simulated cycles)"
                         : fmt::format("no interval yet (needs {} rounds)", cell.rounds_needed);
  if (cell.interval) {
    const int decimals = cell.exact ? 3 : 1;
    note = fmt::format("[{}, {}] {}", signed_percent(interval.lower, decimals),
                       signed_percent(interval.upper, decimals),
                       cell.exact ? "counted (simulated cycles)" : cell.interval_name);
  }
  out += text(302, y + 18, "svg-interval", note);
  out += text(x(threshold) + 3, 16, "svg-note", "limit " + signed_percent(threshold));
  out += x_axis(x, 40, 4, std::max(0, decimals_for(-reach * 100, reach * 100, 4)), "%", 100.0);
  return out + "</svg>";
}

namespace {

// The label of the mark `point` is, or "" when it is none.
std::string mark_of(const TrendPoint& point, const std::vector<TrendMark>& marks) {
  std::string label;
  for (const TrendMark& mark : marks) {
    const std::string& full = point.sha.empty() ? point.short_sha : point.sha;
    const bool same = !mark.sha.empty() && !full.empty() &&
                      (full.starts_with(mark.sha) || mark.sha.starts_with(full));
    if (same) label += (label.empty() ? "" : " = ") + mark.label;
  }
  return label;
}

// How a trend names and prints its values.
struct TrendWords {
  const char* css_class;
  const char* quantity;  // for the plot's label
  const char* unit;      // after a value; "" for the ratio
  int decimals;          // of a value in a tooltip or mark
};

TrendWords trend_words(TrendQuantity quantity) {
  if (quantity == TrendQuantity::peak_memory_mib) {
    return {"plot trend-plot memory-plot", "peak memory (MiB)", " MiB", 1};
  }
  return {"plot trend-plot", "normalized ratio", "", 3};
}

// The y range: the values with a margin. A peak's axis spans at least 2 MiB or 20% of the peak,
// so a few KiB of page-level jitter stay flat, as a compare would judge them (never a verdict).
std::pair<double, double> trend_range(const std::vector<TrendPoint>& points,
                                      TrendQuantity quantity) {
  auto [lo, hi] = padded_range(interval_span(points, &TrendPoint::ratio), 0.1);
  if (quantity != TrendQuantity::peak_memory_mib) return {lo, hi};
  const double span = std::max(2.0, 0.2 * hi);
  if (hi - lo >= span) return {lo, hi};
  const double middle = (lo + hi) / 2.0;
  return {std::max(0.0, middle - span / 2.0), middle + span / 2.0};
}

std::string point_numbers(const TrendPoint& point, const TrendWords& words) {
  if (words.unit[0] != '\0') {
    return fmt::format("peak {:.{}f}{}", point.ratio, words.decimals, words.unit);
  }
  return fmt::format("ratio {:.3f} [{:.3f}, {:.3f}]", point.ratio, point.lower, point.upper);
}

}  // namespace

std::string trend_svg(const TrendSeries& series, const std::vector<TrendMark>& marks,
                      TrendQuantity quantity) {
  const TrendWords words = trend_words(quantity);
  const std::vector<TrendPoint>& p = series.points;
  if (p.empty()) return "";
  const auto [dlo, dhi] = trend_range(p, quantity);
  const int width = 560, height = 210;
  const double left = 52, right = width - 14, top = 18, bottom = height - 50;
  const std::size_t n = p.size();
  auto px = [&](std::size_t i) {
    return n == 1 ? (left + right) / 2
                  : left + (right - left) * static_cast<double>(i) / static_cast<double>(n - 1);
  };
  const Scale y{dlo, dhi, bottom, top};
  std::string out =
      svg_open(width, height, words.css_class,
               fmt::format("{} of {} over {} commits", words.quantity, series.scene, n));
  const int decimals = decimals_for(dlo, dhi, 4);
  for (const double t : ticks(dlo, dhi, 4)) {
    out += fmt::format(R"(<line class="svg-grid" x1="{0}" x2="{1}" y1="{2:.1f}" y2="{2:.1f}"/>)",
                       left, right, y(t));
    out += text(left - 6, y(t) + 4, "svg-tick", fmt::format("{:.{}f}", t, decimals), "end");
  }
  std::string band, line;
  for (std::size_t i = 0; i < n; ++i) band += fmt::format("{:.1f},{:.1f} ", px(i), y(p[i].upper));
  for (std::size_t i = n; i-- > 0;) band += fmt::format("{:.1f},{:.1f} ", px(i), y(p[i].lower));
  for (std::size_t i = 0; i < n; ++i) line += fmt::format("{:.1f},{:.1f} ", px(i), y(p[i].ratio));
  out += fmt::format(R"(<polygon class="trend-band" points="{}"/>)", band);
  out += fmt::format(R"(<polyline class="trend-line" points="{}"/>)", line);
  const std::size_t label_every = (n + 11) / 12;
  std::string labels;  // drawn last, over the line
  for (std::size_t i = 0; i < n; ++i) {
    const TrendPoint& point = p[i];
    // The compare's own commits are marked; a history page (no marks) marks its newest.
    std::string mark = mark_of(point, marks);
    if (marks.empty() && i + 1 == n) mark = "newest";
    std::string title =
        fmt::format("{} {}\n{}", point.short_sha, point.subject, point_numbers(point, words));
    if (!mark.empty()) title = mark + ": " + title;
    if (!point.note.empty()) title += "\n" + point.note;
    out += fmt::format(
        R"(<circle class="trend-point{}{}" cx="{:.1f}" cy="{:.1f}" r="{}"><title>{}</title></circle>)",
        mark.empty() ? "" : " marked", point.flagged ? " flagged" : "", px(i), y(point.ratio),
        mark.empty() ? 3.5 : 5.5, escape(title));
    if (!mark.empty()) {
      const double my = y(point.ratio);
      const char* anchor = i + 1 == n ? "end" : i == 0 ? "start" : "middle";
      labels +=
          text(px(i), my < top + 16 ? my + 17 : my - 9, "trend-mark",
               fmt::format("{} {:.{}f}{}", mark, point.ratio, words.decimals, words.unit), anchor);
    }
    if ((n - 1 - i) % label_every != 0 && mark.empty()) continue;
    out += fmt::format(
        R"svg(<text class="svg-tick sha" transform="translate({:.1f},{:.1f}) rotate(-35)" text-anchor="end">{}</text>)svg",
        px(i) + 3, bottom + 14, escape(point.short_sha));
  }
  out += fmt::format(R"(<line class="svg-axis" x1="{0}" x2="{1}" y1="{2}" y2="{2}"/>)", left, right,
                     bottom);
  return out + labels + "</svg>";
}

}  // namespace raygate::report::html

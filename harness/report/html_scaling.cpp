// The HTML report's scaling section (docs/scaling.md): per scene family a log-log plot of
// seconds against primitives, the baseline's and each tracer role's measured points with their
// fitted lines, and the fits in words beneath, with the compare's exponent verdict on top.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "report/html_parts.h"
#include "scaling/scaling_text.h"

namespace raygate::report::html {
namespace {

struct Series {
  std::string label;
  std::string css_class;                          // scl-baseline, scl-tracer, scl-base, scl-head
  std::vector<std::pair<double, double>> points;  // primitives, seconds
  PowerFit fit;
};

std::vector<Series> series_of(const FamilyScaling& family) {
  std::vector<Series> out;
  Series baseline{"baseline", "scl-baseline", {}, family.baseline};
  for (const ScalingPoint& p : family.points) {
    baseline.points.emplace_back(static_cast<double>(p.primitives), p.baseline_seconds);
  }
  out.push_back(baseline);
  for (const auto& [role, fits] : family.roles) {
    const std::string word(to_string(role));
    Series s{word, "scl-" + word, {}, fits.time};
    for (const ScalingPoint& p : family.points) {
      s.points.emplace_back(static_cast<double>(p.primitives), p.seconds.at(role));
    }
    out.push_back(s);
  }
  return out;
}

// Decades spanned by the values, widened to whole decades.
std::pair<double, double> decades(const std::vector<Series>& series, bool x) {
  double lo = INFINITY, hi = -INFINITY;
  for (const Series& s : series) {
    for (const auto& [n, t] : s.points) {
      const double v = std::log10(x ? n : t);
      lo = std::min(lo, v), hi = std::max(hi, v);
    }
  }
  lo = std::floor(lo), hi = std::ceil(hi);
  if (hi <= lo) hi = lo + 1;
  return {lo, hi};
}

std::string decade_label(double exponent, bool seconds) {
  const double v = std::pow(10.0, exponent);
  if (seconds) return v >= 1 ? fmt::format("{:g} s", v) : fmt::format("{:g} ms", v * 1000);
  return v >= 1e6   ? fmt::format("{:g}M", v / 1e6)
         : v >= 1e3 ? fmt::format("{:g}k", v / 1e3)
                    : fmt::format("{:g}", v);
}

std::string loglog_svg(const FamilyScaling& family) {
  const std::vector<Series> series = series_of(family);
  const auto [xlo, xhi] = decades(series, true);
  const auto [ylo, yhi] = decades(series, false);
  const double left = 62, right = 420, top = 14, bottom = 250;
  const auto px = [&](double n) {
    return left + (std::log10(n) - xlo) / (xhi - xlo) * (right - left);
  };
  const auto py = [&](double t) {
    return bottom - (std::log10(t) - ylo) / (yhi - ylo) * (bottom - top);
  };
  std::string out = fmt::format(
      R"(<svg class="plot scaling-plot" viewBox="0 0 560 290" width="560" height="290" role="img" aria-label="{}">)",
      escape(fmt::format("seconds against primitives, log-log, {}", family.family)));
  for (double d = xlo; d <= xhi + 1e-9; d += 1) {
    out += fmt::format(R"(<line class="svg-grid" x1="{0:.1f}" x2="{0:.1f}" y1="{1}" y2="{2}"/>)",
                       px(std::pow(10.0, d)), top, bottom);
    out += fmt::format(R"(<text x="{:.1f}" y="{}" class="svg-tick" text-anchor="middle">{}</text>)",
                       px(std::pow(10.0, d)), bottom + 16, decade_label(d, false));
  }
  for (double d = ylo; d <= yhi + 1e-9; d += 1) {
    out += fmt::format(R"(<line class="svg-grid" x1="{0}" x2="{1}" y1="{2:.1f}" y2="{2:.1f}"/>)",
                       left, right, py(std::pow(10.0, d)));
    out += fmt::format(R"(<text x="{}" y="{:.1f}" class="svg-tick" text-anchor="end">{}</text>)",
                       left - 6, py(std::pow(10.0, d)) + 4, decade_label(d, true));
  }
  out +=
      fmt::format(R"(<text x="{}" y="{}" class="svg-tick" text-anchor="middle">primitives</text>)",
                  (left + right) / 2, bottom + 32);
  double legend_y = top + 10;
  for (const Series& s : series) {
    const double n0 = s.points.front().first, n1 = s.points.back().first;
    out += fmt::format(
        R"(<g class="{}"><line class="scl-fit" x1="{:.1f}" y1="{:.1f}" x2="{:.1f}" y2="{:.1f}"/>)",
        s.css_class, px(n0), py(s.fit.predict(n0)), px(n1), py(s.fit.predict(n1)));
    for (const auto& [n, t] : s.points) {
      out +=
          fmt::format(R"(<circle cx="{:.1f}" cy="{:.1f}" r="4"><title>{}</title></circle>)", px(n),
                      py(t), escape(fmt::format("{} {:.0f} primitives: {:.4f} s", s.label, n, t)));
    }
    out += fmt::format(R"(<circle cx="{}" cy="{:.1f}" r="4"/>)", right + 14, legend_y - 4);
    out += fmt::format(R"(<text x="{}" y="{:.1f}" class="svg-value">{} k={:.2f}</text></g>)",
                       right + 24, legend_y, escape(s.label), s.fit.exponent);
    legend_y += 18;
  }
  return out + "</svg>";
}

std::string family_block(const FamilyScaling& family) {
  std::string html = fmt::format(R"(<div class="scaling-family" id="scaling-{}"><h3>{}</h3>)",
                                 anchor(family.family), escape(family.family));
  if (family.change) {
    const bool bad = family.change->verdict == ChangeVerdict::regressed;
    html += fmt::format(R"(<p class="{}">{}</p>)", bad ? "v-fail" : "muted",
                        escape(describe_change(family.family, *family.change)));
  }
  html += loglog_svg(family) + "<ul class=\"scaling-fits\">";
  html += fmt::format("<li><b>baseline</b> {}</li>", escape(describe_fit(family.baseline)));
  for (const auto& [key, fits] : family.roles) {
    const std::string_view role = to_string(key);
    html += fmt::format("<li><b>{0}</b> {1}</li><li><b>{0} ratio</b> {2}</li>", escape(role),
                        escape(describe_fit(fits.time)), escape(describe_fit(fits.ratio)));
  }
  return html + "</ul></div>";
}

}  // namespace

std::string scaling_section(const ResultsDocument& document) {
  if (!document.scaling || document.scaling->families.empty()) return "";
  const ScalingAnalysis& analysis = *document.scaling;
  std::string html =
      R"(<section class="card scaling" id="scaling"><h2>Growth with scene size</h2>)"
      R"(<p class="muted">Seconds against primitives, both axes logarithmic: the slope k is the )"
      R"(growth exponent of t ≈ c·n<sup>k</sup> (1: linear, like the baseline; near 0: a working )"
      R"(acceleration structure). Lines are least-squares fits; intervals are 95%.</p>)";
  for (const FamilyScaling& family : analysis.families) html += family_block(family);
  return html + "</section>";
}

}  // namespace raygate::report::html

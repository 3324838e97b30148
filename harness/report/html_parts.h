// The pieces of the HTML report (html_reporter.cpp puts them together): text escaping and
// embedded images, inline SVG plots, the per-scene section, the page's style and script. The
// page is one self-contained file: images are data: URIs, CSS and JS are inline, nothing is
// fetched, so it can be archived as a CI artifact and opened years later, offline.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "report/report_model.h"

namespace raygate::report::html {

// Text and attribute values: & < > " ' escaped, control characters and bidi overrides shown
// as visible escapes (core/sanitize.h markup_text).
std::string escape(std::string_view text);
std::string base64(std::string_view bytes);
// A data: URI for an image file. PNG, JPEG, GIF and WebP are embedded as they are; any other
// format OpenImageIO reads (PPM, EXR, TGA, HDR...) is converted to PNG first. nullopt when the
// file is missing or unreadable.
std::optional<std::string> image_data_uri(const std::filesystem::path& path);
// "gate-pass", "gate-fail", ... (CSS classes).
std::string outcome_class(GateOutcome outcome);
// A pill with the outcome in capitals.
std::string badge(GateOutcome outcome);
// An identifier usable as an HTML id: letters, digits and '-' only.
std::string anchor(std::string_view scene_id);

// One labelled interval on a horizontal axis.
struct IntervalRow {
  std::string label;
  double value = 0.0;
  double lower = 0.0;
  double upper = 0.0;
  std::string css_class;  // colour of the mark
};

// The ratios' CIs of one scene on a shared axis (one row per revision).
std::string ratio_bars_svg(const std::vector<IntervalRow>& rows);
// The change and the interval that decided it against the ±threshold band, in percent; the
// point alone while the interval is unbounded or the change exact.
std::string change_bar_svg(const ChangeCell& cell, double threshold, const std::string& css_class);
// A commit the trend marks and names: the compare's base and head, or the run's tracer.
struct TrendMark {
  std::string sha;    // full id, or a prefix of one (a short sha)
  std::string label;  // "base", "head", "this run"
};
// What a trend plots in its points' `ratio` (and band, lower..upper): the normalized ratio, or
// the peak resident memory in MiB (issue 27; no band: a peak is one median per commit).
enum class TrendQuantity { normalized_ratio, peak_memory_mib };
// The normalized ratio over commits: CI band, line, points with tooltips. The points of `marks`
// are drawn large and labelled; without marks, the newest point is (a history page).
std::string trend_svg(const TrendSeries& series, const std::vector<TrendMark>& marks = {},
                      TrendQuantity quantity = TrendQuantity::normalized_ratio);

// <section> of the scaling analysis (html_scaling.cpp): a log-log plot per scene family with
// the fitted growth; "" when the document has none.
std::string scaling_section(const ResultsDocument& document);

// <section> of one scene: badge, reasons, numbers, plots, images, metrics.
std::string scene_section(const ReportInput& input, const SceneView& view);

std::string page_style();
std::string_view page_script();

}  // namespace raygate::report::html

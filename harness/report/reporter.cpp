#include "report/reporter.h"

#include <fmt/format.h>

#include <array>
#include <iostream>
#include <sstream>
#include <utility>

#include "core/error.h"
#include "core/fs.h"
#include "report/reporters.h"

namespace raygate {
namespace {

constexpr std::array<std::pair<std::string_view, ReportFormat>, 5> kFormats{{
    {"console", ReportFormat::console},
    {"markdown", ReportFormat::markdown},
    {"junit", ReportFormat::junit},
    {"json", ReportFormat::json},
    {"html", ReportFormat::html},
}};

bool is_stdout(const std::filesystem::path& path) { return path.empty() || path == "-"; }

}  // namespace

const TrendSeries* ReportInput::trend(const std::string& scene) const {
  for (const TrendSeries& series : trends) {
    if (series.scene == scene && !series.points.empty()) return &series;
  }
  return nullptr;
}

ReportFormat parse_report_format(std::string_view name) {
  for (const auto& [text, format] : kFormats) {
    if (text == name) return format;
  }
  throw UsageError(fmt::format("unknown report format '{}'; use one of {}", name,
                               fmt::join(report_format_names(), ", ")));
}

std::vector<std::string> report_format_names() {
  std::vector<std::string> names;
  for (const auto& entry : kFormats) names.emplace_back(entry.first);
  return names;
}

std::string report_format_list() {
  const std::vector<std::string> names = report_format_names();
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) {
    list += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  }
  return list;
}

std::string_view to_string(ReportFormat format) {
  for (const auto& [text, known] : kFormats) {
    if (known == format) return text;
  }
  return "console";
}

std::unique_ptr<Reporter> make_reporter(ReportFormat format, const ReportOptions& options) {
  switch (format) {
    case ReportFormat::console: return report::make_console_reporter(options);
    case ReportFormat::markdown: return report::make_markdown_reporter(options);
    case ReportFormat::junit: return report::make_junit_reporter(options);
    case ReportFormat::json: return report::make_json_reporter(options);
    case ReportFormat::html: return report::make_html_reporter(options);
  }
  return report::make_console_reporter(options);
}

std::unique_ptr<Reporter> make_reporter(std::string_view format, const ReportOptions& options) {
  return make_reporter(parse_report_format(format), options);
}

void write_reports(const ReportInput& input, const std::vector<ReportTarget>& targets,
                   const ReportOptions& options) {
  for (const ReportTarget& target : targets) {
    ReportOptions these = options;
    these.colour = options.colour && is_stdout(target.path);
    const std::unique_ptr<Reporter> reporter = make_reporter(target.format, these);
    if (is_stdout(target.path)) {
      reporter->write(input, std::cout);
      std::cout.flush();
      continue;
    }
    std::ostringstream text;
    reporter->write(input, text);
    write_file_atomically(target.path, text.str());
  }
}

}  // namespace raygate

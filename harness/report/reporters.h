// The concrete reporters, one factory per format; make_reporter (reporter.h) picks among them.
// Internal to report/: everything outside asks for a format by name.
#pragma once

#include <memory>

#include "report/reporter.h"

namespace raygate::report {

std::unique_ptr<Reporter> make_console_reporter(const ReportOptions& options);
std::unique_ptr<Reporter> make_markdown_reporter(const ReportOptions& options);
std::unique_ptr<Reporter> make_junit_reporter(const ReportOptions& options);
std::unique_ptr<Reporter> make_json_reporter(const ReportOptions& options);
std::unique_ptr<Reporter> make_html_reporter(const ReportOptions& options);

}  // namespace raygate::report

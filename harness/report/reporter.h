// Reporters (DESIGN.md §2: verdict --report--> terminal / md / junit / html / json): one
// interface, five formats. Each turns a results document, the gate's verdict on it and the
// policy that verdict used into text for one audience: a person at a terminal, a pull-request
// comment, a CI test tab, a bot, or a reviewer looking at pictures. Reporters only read; they
// never measure, judge or change anything, so every format tells the same story.
#pragma once

#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "gate/policy.h"
#include "gate/verdict.h"
#include "results/results.h"

namespace raygate {

// One commit's normalized ratio of one scene, from the store's history.
struct TrendPoint {
  std::string short_sha;
  std::string subject;
  std::string commit_time;  // ISO-8601; may be empty
  double ratio = 0.0;
  double lower = 0.0;  // the ratio's 95% CI
  double upper = 0.0;
  std::string note;      // more for the point's tooltip (the image check); may be empty
  bool flagged = false;  // drawn in the failure colour: the image check failed
  std::string sha;       // the full commit id, to mark the report's own commits; may be empty
};

// A scene's history, oldest commit first. The store fills these; a report without history
// gets none, and a scene without a series gets no trend plot.
struct TrendSeries {
  std::string scene;  // suite scene id
  std::vector<TrendPoint> points;
};

struct ReportInput {
  const ResultsDocument& document;
  const GateResult& gate;
  const GatePolicy& policy;
  std::vector<TrendSeries> trends;
  // Relative image paths in the document are resolved against this (the document's folder).
  std::filesystem::path base_dir;
  // Outputs that could not be written before the table (issue 40: its closing line said "exit 0"
  // while raygate exited 3): what failed, and the exit code raygate will really end with.
  std::string outputs_failed;
  int exit_code_with_outputs = 0;

  int exit_code() const { return outputs_failed.empty() ? gate.exit_code : exit_code_with_outputs; }
  const TrendSeries* trend(const std::string& scene) const;
};

enum class ReportFormat { console, markdown, junit, json, html };

struct ReportOptions {
  bool colour = false;  // console: ANSI colours (the caller decides, e.g. from isatty)
  // GitHub's comment limit is 65536 bytes; room is left for a marker a poster adds (ci/pr-comment
  // adds one line: a report at the limit was refused once it was added).
  std::size_t markdown_limit = 65000;
};

class Reporter {
 public:
  virtual ~Reporter() = default;
  virtual void write(const ReportInput& input, std::ostream& out) const = 0;
};

// Throws UsageError naming the known formats for an unknown name.
ReportFormat parse_report_format(std::string_view name);
// The formats' names in their order ("console", "markdown", ...), and as prose: "console,
// markdown, junit, json or html" (for the command line's choices and help).
std::vector<std::string> report_format_names();
std::string report_format_list();
std::string_view to_string(ReportFormat format);
std::unique_ptr<Reporter> make_reporter(ReportFormat format, const ReportOptions& options = {});
std::unique_ptr<Reporter> make_reporter(std::string_view format, const ReportOptions& options = {});

struct ReportTarget {
  ReportFormat format = ReportFormat::console;
  std::filesystem::path path;  // "-" or empty: standard output
};

// Writes each report: files atomically (core/fs.h), "-" to std::cout. Colour (options.colour)
// applies only to standard output; a file never gets escape codes.
void write_reports(const ReportInput& input, const std::vector<ReportTarget>& targets,
                   const ReportOptions& options = {});

}  // namespace raygate

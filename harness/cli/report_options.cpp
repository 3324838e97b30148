#include "cli/report_options.h"

#include <fmt/core.h>
#include <unistd.h>

#include <cerrno>
#include <iostream>
#include <cstring>

#include "cli/terminal_progress.h"
#include "core/error.h"
#include "history/store_trends.h"
#include "report/reporter.h"

namespace raygate::cli {

namespace {

std::vector<ReportTarget> parse_specs(const std::vector<std::string>& reports) {
  std::vector<ReportTarget> targets;
  for (const std::string& spec : reports) {
    const std::size_t colon = spec.find(':');
    if (colon == std::string::npos || colon + 1 == spec.size()) {
      throw UsageError(fmt::format("--report {}: expected FORMAT:PATH, e.g. html:report.html", spec));
    }
    targets.push_back({parse_report_format(spec.substr(0, colon)), spec.substr(colon + 1)});
  }
  return targets;
}

}  // namespace

void add_report_options(CLI::App& command, std::vector<std::string>& reports) {
  command.add_option("--report", reports,
                     "also write a report: FORMAT:PATH with FORMAT markdown, junit, json, html or "
                     "console (repeatable; PATH - is standard output)");
  command
      .add_option_function<std::string>(
          "--format", [&reports](const std::string& format) { reports.push_back(format + ":-"); },
          "print a report on standard output: console, markdown, junit, json or html (the "
          "same as --report FORMAT:-)")
      ->check(CLI::IsMember({"console", "markdown", "junit", "json", "html"}));
}

void check_report_specs(const std::vector<std::string>& reports) {
  for (const ReportTarget& target : parse_specs(reports)) {
    if (target.path != "-") check_output_path(target.path, "--report " + target.path.string());
  }
}

void check_output_path(const std::filesystem::path& path, const std::string& option) {
  if (path.empty()) return;
  std::error_code error;
  const std::filesystem::path target = std::filesystem::absolute(path, error);
  if (std::filesystem::is_directory(target, error)) {
    throw UsageError(fmt::format("{}: {} is a directory; name a file in it", option,
                                 target.string()));
  }
  if (std::filesystem::exists(target, error) && !std::filesystem::is_regular_file(target, error)) {
    // Files are replaced whole (a temporary renamed over them): that would replace the node.
    throw UsageError(fmt::format("{}: {} is not a regular file (a device, FIFO or socket); name "
                                 "a file, or - for standard output",
                                 option, target.string()));
  }
  std::filesystem::path folder = target.parent_path();
  while (!std::filesystem::exists(folder, error) && folder.has_relative_path()) {
    folder = folder.parent_path();  // created when the file is written
  }
  if (!std::filesystem::is_directory(folder, error)) {
    throw UsageError(fmt::format("{}: cannot write {}: {} is not a directory", option,
                                 target.string(), folder.string()));
  }
  if (::access(folder.c_str(), W_OK | X_OK) != 0) {
    throw UsageError(fmt::format("{}: cannot write {}: {}: {}", option, target.string(),
                                 folder.string(), std::strerror(errno)));
  }
}

int record_gate_and_report(const ResultsDocument& document, const std::filesystem::path& path,
                           const RecordArgs& record, const std::filesystem::path& cache_dir,
                           const GatePolicy& policy, const std::vector<std::string>& reports,
                           const Console& console, OutputFailures& failures) {
  if (!failures.failed(path)) console.info(fmt::format("results: {}", path.string()));
  record_results(document, record, cache_dir, path, console);
  const GateResult gate = evaluate_gate(document, policy);
  StoreTrends trends = trends_from_store(record_store_path(record, cache_dir), document);
  if (!trends.warning.empty()) console.warning(trends.warning);
  emit_reports(document, gate, policy, reports, path, console, failures,
               std::move(trends.trends));
  failures.say_summary(failures.exit_code(gate.exit_code));
  return failures.exit_code(gate.exit_code);
}

void emit_reports(const ResultsDocument& document, const GateResult& gate,
                  const GatePolicy& policy, const std::vector<std::string>& reports,
                  const std::filesystem::path& document_path, const Console& console,
                  OutputFailures& failures, std::vector<TrendSeries> trends) {
  const std::vector<ReportTarget> targets = parse_specs(reports);
  ReportInput input{document, gate, policy, std::move(trends), document_path.parent_path()};
  if (!console.quiet()) {  // the table for whoever watches: standard error, as all chatter
    ReportOptions table;
    table.colour = console.colour(stderr);
    std::fflush(stderr);
    make_reporter(ReportFormat::console, table)->write(input, std::cerr);
    std::cerr.flush();
  }
  ReportOptions options;
  options.colour = console.colour(stdout);
  for (const ReportTarget& target : targets) {
    const std::string output =
        fmt::format("--report {}:{}", to_string(target.format), target.path.string());
    int error_number = 0;  // why standard output failed, before anything else sets errno
    const bool written = failures.attempt(output, [&] {
      errno = 0;
      write_reports(input, {target}, options);
      error_number = errno;
    });
    if (target.path == "-") {
      check_standard_output(failures, output, error_number);
    } else if (written) {
      console.info(fmt::format("{} report: {}", to_string(target.format), target.path.string()));
    }
  }
}

}  // namespace raygate::cli

#include "cli/report_options.h"

#include <fmt/core.h>

#include "cli/progress.h"
#include "core/error.h"
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
}

void check_report_specs(const std::vector<std::string>& reports) { (void)parse_specs(reports); }

void emit_reports(const ResultsDocument& document, const GateResult& gate,
                  const GatePolicy& policy, const std::vector<std::string>& reports,
                  const std::filesystem::path& document_path) {
  std::vector<ReportTarget> targets = parse_specs(reports);
  targets.insert(targets.begin(), ReportTarget{ReportFormat::console, "-"});
  ReportInput input{document, gate, policy, {}, document_path.parent_path()};
  ReportOptions options;
  options.colour = is_terminal(stdout);
  std::fflush(stdout);
  write_reports(input, targets, options);
  for (std::size_t i = 1; i < targets.size(); ++i) {
    fmt::print("{} report: {}\n", to_string(targets[i].format), targets[i].path.string());
  }
}

}  // namespace raygate::cli

#include "cli/report_options.h"

#include <iostream>

namespace raygate::cli {

void add_report_options(CLI::App& command, std::vector<std::string>& reports) {
  command.add_option("--report", reports,
                     "also write a report: FORMAT:PATH with FORMAT " + report_format_list() +
                         " (repeatable; PATH - is standard output)");
  command
      .add_option_function<std::string>(
          "--format", [&reports](const std::string& format) { reports.push_back(format + ":-"); },
          "print a report on standard output: " + report_format_list() +
              " (the same as --report FORMAT:-)")
      ->check(CLI::IsMember(report_format_names()));
}

void add_publish_options(CLI::App& command, std::string& output, const std::string& output_help,
                         RecordArgs& record, std::vector<std::string>& reports) {
  add_deprecated_alias(command, "--out", command.add_option("-o,--output", output, output_help),
                       output);
  add_record_options(command, record);
  add_report_options(command, reports);
}

PublishRequest publish_request(const std::filesystem::path& document_path,
                               const RecordArgs& record, const std::filesystem::path& cache_dir,
                               const GatePolicy& policy, const std::vector<std::string>& reports,
                               const Console& console) {
  PublishRequest request;
  request.document_path = document_path;
  if (!record.no_store) {
    request.store = record.store.empty() ? cache_dir / "results.db"
                                         : std::filesystem::path(record.store);
  }
  request.branch = record.branch;
  request.policy = policy;
  request.reports = parse_report_targets(reports);
  if (!console.quiet()) request.table = &std::cerr;  // chatter: standard error
  request.table_colour = console.colour(stderr);
  request.report_colour = console.colour(stdout);
  return request;
}

int publish_measured(const MeasuredDocument& measured, const RecordArgs& record,
                     const std::filesystem::path& cache_dir, const GatePolicy& policy,
                     const std::vector<std::string>& reports, const Console& console) {
  OutputFailures failures;
  for (const FailedWrite& failed : measured.unwritten) failures.add("the results document", failed);
  return publish(measured.document,
                 publish_request(measured.path, record, cache_dir, policy, reports, console),
                 console, failures);
}

}  // namespace raygate::cli

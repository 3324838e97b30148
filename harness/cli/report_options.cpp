#include "cli/report_options.h"

#include "cli/console.h"

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
                         PublishOptions& options) {
  add_deprecated_alias(command, "--out", command.add_option("-o,--output", output, output_help),
                       output);
  add_record_options(command, options);
  add_report_options(command, options.reports);
}

}  // namespace raygate::cli

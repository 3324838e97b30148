// `raygate report RESULTS.json`: the gate's verdict on a stored results document, written in
// one of the report formats (console, markdown, junit, json, html) to standard output or a
// file. Exits 0 once the report is written, whatever the verdict (a report step should not fail
// a CI job by itself); --exit-code makes it exit with the gate's code instead.
#include "cli/commands.h"
#include "cli/console.h"
#include "cli/subcommand.h"
#include "pipeline/document_commands.h"
#include "pipeline/output_failures.h"
#include "report/reporter.h"

namespace raygate::cli {
namespace {

struct ReportArgs {
  std::string results;
  std::string format = "console";
  std::string output = "-";
  std::string policy;
  bool exit_code = false;
};

int report_command(const ReportArgs& args, const Console& console) {
  const ReportFormat format = parse_report_format(args.format);
  check_distinct_files({{"the results document", args.results},
                        {"--policy", args.policy},
                        {"--output", args.output}});
  std::string note;
  const JudgedDocument j = judge_document(args.results, args.policy, false, note);
  ReportOptions options;
  options.colour = console.colour(args.output.empty() || args.output == "-" ? stdout : nullptr);
  write_reports({j.document, j.gate, j.policy, {}, j.path.parent_path(), {}, 0},
                {{format, args.output}}, options);
  return args.exit_code ? j.gate.exit_code : 0;
}

}  // namespace

void add_report_command(CLI::App& command, int& exit_code) {
  ReportArgs& args = bind_command<ReportArgs>(command, report_command, exit_code);
  command.add_option("results", args.results, "results document (raygate run/compare --out)")
      ->required()
      ->check(CLI::ExistingFile);
  command.add_option("--format", args.format, report_format_list())
      ->check(CLI::IsMember(report_format_names()))
      ->capture_default_str();
  command.add_option("-o,--output", args.output, "file to write; '-' for standard output")
      ->capture_default_str()
      ->check(writable_file());
  command
      .add_option("--policy", args.policy,
                  "gate policy file (default: the limits the document was measured under, as gate)")
      ->check(CLI::ExistingFile);
  command.add_flag("--exit-code", args.exit_code,
                   "exit with the gate's code (0 pass, 1 regression, 3 not measured)");
  // --color is the global option (cli/console.h), accepted after `report` too.
}

}  // namespace raygate::cli

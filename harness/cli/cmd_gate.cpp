// `raygate gate RESULTS.json [--policy FILE]`: the verdict on a results document that was
// measured earlier (or on another machine, or merged from shards), under a policy; --format json
// prints the JSON report (docs/reports.md) instead of the summary. The exit code is the gate's:
// 0 pass, 1 regression, 2 usage, 3 the document says something was not measured.
#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/subcommand.h"
#include "pipeline/document_commands.h"
#include "report/gate_summary.h"
#include "report/reporter.h"

namespace raygate::cli {
namespace {

struct GateArgs {
  std::string results;
  std::string policy;
  bool fail_on_inconclusive = false;
  std::string format;  // text, json
};

int gate_command(const GateArgs& args, const Console& console) {
  std::string note;
  const JudgedDocument j =
      judge_document(args.results, args.policy, args.fail_on_inconclusive, note);
  if (!note.empty()) console.info(fmt::format("gate policy: {}", note));
  if (args.format == "json") {
    write_reports({j.document, j.gate, j.policy, {}, j.path.parent_path(), {}, 0},
                  {{ReportFormat::json, "-"}}, {});
  } else {
    print_gate_summary(j.gate, stdout);
  }
  return j.gate.exit_code;
}

}  // namespace

void add_gate_command(CLI::App& command, int& exit_code) {
  GateArgs& args = bind_command<GateArgs>(command, gate_command, exit_code);
  command.add_option("results", args.results, "results document (from run or compare)")->required();
  command.add_option("--policy", args.policy, "gate policy file (docs/gate.md)")
      ->check(CLI::ExistingFile);  // raygate.toml's policy is then named with its line
  command.add_flag("--fail-on-inconclusive", args.fail_on_inconclusive,
                   "an INCONCLUSIVE change fails the gate instead of warning");
  add_format_option(command, args.format, {"text", "json"});
}

}  // namespace raygate::cli

// `raygate scaling RESULTS.json`: the complexity gate on a run or compare document (usually of
// the `scaling` suite): each scene family's growth exponent, and for a compare its change judged
// against the policy. Fits again and writes them into the document (no report may name it) unless
// --no-write. Exit 0 pass, 1 an exponent regressed, 2 no family measured at 3 sizes or more.
#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/report_options.h"
#include "cli/subcommand.h"
#include "pipeline/document_commands.h"
#include "report/gate_summary.h"
#include "scaling/scaling_text.h"

namespace raygate::cli {
namespace {

struct ScalingArgs {
  std::string results;
  std::string policy;
  bool no_write = false;
  PublishOptions publish = [] {
    PublishOptions p;
    p.no_store = true;  // scaling writes the fits into the document, never to the store
    return p;
  }();
};

int scaling_command(const ScalingArgs& args, const Console& console) {
  check_publish_targets(args.publish, args.results, "the results document",
                        {{"--policy", args.policy}});
  OutputFailures failures;
  const ScalingJudgement j = judge_scaling(args.results, args.policy, args.no_write, failures);
  for (const std::string& line : scaling_lines(j.analysis)) fmt::print("{}\n", line);
  print_gate_summary(j.gate, stdout);
  if (!args.publish.reports.empty()) {  // the scene table is run's and compare's; on request
    publish_reports(j.document, evaluate_gate(j.document, j.policy),
                    publish_request(args.publish, args.results, {}, j.policy, console), console,
                    failures);
  }
  failures.say_summary(failures.exit_code(j.gate.exit_code));
  return failures.exit_code(j.gate.exit_code);
}

}  // namespace

void add_scaling_command(CLI::App& command, int& exit_code) {
  ScalingArgs& args = bind_command<ScalingArgs>(command, scaling_command, exit_code);
  command
      .add_option("results", args.results,
                  "results document (run or compare of a suite "
                  "with 3+ sizes per scene, e.g. --suite scaling)")
      ->required();
  command.add_option("--policy", args.policy,
                     "gate policy file (max_exponent_increase, max_slowdown; docs/gate.md)");
  command.add_flag("--no-write", args.no_write, "do not write the fits into the document");
  add_report_options(command, args.publish.reports);
}

}  // namespace raygate::cli

// `raygate scaling RESULTS.json`: the complexity gate on a document that run or compare wrote
// (usually of the `scaling` suite): each scene family's growth exponent for the baseline and the
// tracer, and for a compare the change of exponent judged against the policy. Fits again and
// writes them into the document unless --no-write. Exit 0 pass, 1 an exponent regressed, 2 no
// family measured at 3 sizes or more.
#include <fmt/core.h>

#include <algorithm>
#include <memory>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/gate_summary.h"
#include "cli/report_options.h"
#include "core/error.h"
#include "gate/growth_gate.h"
#include "scaling/scaling_stage.h"
#include "scaling/scaling_text.h"

namespace raygate::cli {
namespace {

struct ScalingArgs {
  std::string results;
  std::string policy;
  bool no_write = false;
  std::vector<std::string> reports;
};

int scaling_command(const ScalingArgs& args, const Console& console) {
  check_report_specs(args.reports);
  ResultsDocument document = read_results(args.results);
  std::string note;
  const GatePolicy policy =
      args.policy.empty() ? recorded_policy(document.settings, note) : load_policy(args.policy);
  const ScalingAnalysis analysis = attach_scaling(document, scaling_limits(policy));
  if (analysis.families.empty()) {
    throw UsageError(fmt::format("{}: no scene family was measured at 3 sizes or more (suite {}); "
                                 "measure the scaling suite: --suite scaling",
                                 args.results, document.suite));
  }
  for (const std::string& line : scaling_lines(analysis)) fmt::print("{}\n", line);
  OutputFailures failures;  // the fits not written back still judge, and reports still go out
  if (!args.no_write) {
    failures.attempt("the fits in " + args.results, [&] { write_results(document, args.results); });
  }
  GateResult gate;
  gate.families = judge_growth(document, policy);
  const bool failed = std::any_of(gate.families.begin(), gate.families.end(),
                                  [](const SceneGate& g) { return g.outcome == GateOutcome::fail; });
  gate.exit_code = failed ? 1 : 0;
  print_gate_summary(gate, stdout);
  if (!args.reports.empty()) {  // the scene table is run's and compare's; shown only on request
    emit_reports(document, evaluate_gate(document, policy), policy, args.reports, args.results,
                 console, failures);
  }
  failures.say_summary(failures.exit_code(gate.exit_code));
  return failures.exit_code(gate.exit_code);
}

}  // namespace

void add_scaling_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<ScalingArgs>();
  CLI::App* command = app.add_subcommand(
      "scaling", "fit how time grows with scene size per scene family; judge a compare's change");
  command->add_option("results", args->results, "results document (run or compare of a suite "
                                                 "with 3+ sizes per scene, e.g. --suite scaling)")
      ->required();
  command->add_option("--policy", args->policy,
                      "gate policy file (max_exponent_increase, max_slowdown; docs/gate.md)");
  command->add_flag("--no-write", args->no_write, "do not write the fits into the document");
  add_report_options(*command, args->reports);
  command->callback([args, command, &exit_code] {
    exit_code = scaling_command(*args, console_of(*command));
  });
}

}  // namespace raygate::cli

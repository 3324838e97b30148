// `raygate compare`: base and head of a tracer measured in the same job, in rounds that rotate
// (baseline, base, head), so drift hits all three alike; per scene the change of the normalized
// ratio with its CI and a verdict, images against the goldens and head's against base's; then
// the gate. Exit 0 pass, 1 regression, 2 usage, 3 could not measure.
#include "cli/commands.h"
#include "cli/console.h"
#include "cli/measure_options.h"
#include "cli/report_options.h"
#include "cli/subcommand.h"
#include "pipeline/terminal_progress.h"
#include "core/error.h"
#include "pipeline/compare_measurement.h"
#include "pipeline/revision_setup.h"

namespace raygate::cli {
namespace {

struct CompareArgs {
  MeasureArgs measure;
  std::string base;
  std::string base_branch;
  std::string head = "HEAD";
  std::string out;
  bool fail_on_inconclusive = false;
  bool explain = false;  // --explain: profile REGRESSED scenes once each (pipeline/explain_stage.h)
  PublishOptions publish;  // --store, --no-store, --branch, --report, --format
};

int compare_command(const CompareArgs& args, const Console& console) {
  if (args.base.empty() == args.base_branch.empty()) {
    throw UsageError("name the base: --base REV or --base-branch BRANCH (exactly one)");
  }
  MeasureContext context = load_measure_context(args.measure);
  context.explain = args.explain;
  check_publish_targets(args.publish, args.out, "--output", context.input_files);
  const BaselineTool baseline(context.tools.baseline);
  const CompareTrees trees = locate_compare_trees(args.measure.repo, args.base, args.base_branch,
                                                  args.head, context.cache_dir);
  TerminalIo terminal(console.quiet(), is_terminal(stderr));
  const MeasuredDocument measured = measure_compare(
      {context, baseline, trees.repository, trees.base, trees.head, args.out}, terminal.io);
  GatePolicy policy = context.policy;
  policy.fail_on_inconclusive = policy.fail_on_inconclusive || args.fail_on_inconclusive;
  return publish_measured(measured, args.publish, context.cache_dir, policy, console);
}

}  // namespace

void add_compare_command(CLI::App& command, int& exit_code) {
  CompareArgs& args = bind_command<CompareArgs>(command, compare_command, exit_code);
  add_change_measure_options(command, args.measure);
  add_shard_options(command, args.measure);
  command.add_option("--base", args.base, "base revision");
  command.add_option("--base-branch", args.base_branch,
                     "use the merge base of head and this branch as the base");
  command.add_option("--head", args.head, "head revision")->capture_default_str();
  command.add_flag("--fail-on-inconclusive", args.fail_on_inconclusive,
                   "an INCONCLUSIVE change fails the gate instead of warning");
  command.add_flag("--explain", args.explain,
                   "run each REGRESSED scene's base and head once more under valgrind's "
                   "callgrind and show the functions whose instructions grew most (sim mode "
                   "explains from its own cachegrind files without it)");
  add_publish_options(
      command, args.out,
      "results document (default: <cache-dir>/runs/<time>-<base>-<head>/results.json)",
      args.publish);
}

}  // namespace raygate::cli

// `raygate run`: measure one revision of a tracer against the baseline on a suite and write the
// results document. Options -> a run request -> the pipeline (pipeline/run_measurement.h:
// build, then per scene runs, ratios, image checks, document rewritten) -> summary, store,
// gate, reports. Exit 0 measured and images pass, 1 an image check failed, 3 a scene could not
// be measured (the document says which and why).
#include <fmt/core.h>

#include <memory>

#include "checkout/repository.h"
#include "cli/commands.h"
#include "cli/console.h"
#include "cli/measure_options.h"
#include "cli/report_options.h"
#include "cli/store_options.h"
#include "cli/terminal_io.h"
#include "gate/verdict.h"
#include "pipeline/run_measurement.h"
#include "runner/baseline_tool.h"

namespace raygate::cli {
namespace {

struct RunArgs {
  MeasureArgs measure;
  std::string rev = "HEAD";
  std::string worktree;
  std::string out;
  RecordArgs record;  // --store, --no-store, --branch
  std::vector<std::string> reports;  // --report FORMAT:PATH
};

// The commit to measure, or the user's own tree as it is (--worktree, recorded as dirty).
std::pair<Worktree, std::string> locate_tree(const RunArgs& args, const MeasureContext& context) {
  if (!args.worktree.empty()) {
    const std::filesystem::path path = std::filesystem::absolute(args.worktree);
    Worktree tree = describe_uncommitted_worktree(path);
    tree.revision = "--worktree " + path.string();
    return {tree, path.string()};
  }
  const Repository repository = Repository::open(args.measure.repo, context.cache_dir);
  return {repository.checkout(args.rev), repository.location()};
}

int run_command(const RunArgs& args, const Console& console) {
  const MeasureContext context = load_measure_context(args.measure);
  check_report_specs(args.reports);
  check_output_path(args.out, "--output");
  const BaselineTool baseline(context.tools.baseline);
  const auto [worktree, repository] = locate_tree(args, context);
  TerminalIo terminal(console);
  const MeasuredDocument measured =
      measure_run({context, baseline, repository, worktree, args.out}, terminal.io);
  const ResultsDocument& document = measured.document;
  if (const auto score = document.scores.find(role_name(Role::tracer));
      score != document.scores.end()) {
    console.info(fmt::format("suite score (geometric mean of normalized ratios): {:.3f} [{:.3f}, "
                             "{:.3f}] over {} scenes",
                             score->second.score, score->second.interval.lower,
                             score->second.interval.upper, score->second.scenes));
  }
  OutputFailures failures;
  for (const FailedWrite& failed : measured.unwritten) failures.add("the results document", failed);
  return record_gate_and_report(document, measured.path, args.record, context.cache_dir,
                                context.policy, args.reports, console, failures);
}

}  // namespace

void add_run_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* command = app.add_subcommand(
      "run", "measure one revision against the baseline on a suite; writes a results document");
  add_measure_options(*command, args->measure);
  add_shard_options(*command, args->measure);
  command->add_option("--rev", args->rev, "revision to measure (branch, tag, sha, HEAD~3, ...)")
      ->capture_default_str();
  command->add_option("--worktree", args->worktree,
                      "measure this directory as it is, uncommitted changes included");
  add_deprecated_alias(*command, "--out",
                       command->add_option("-o,--output", args->out,
                                           "results document (default: "
                                           "<cache-dir>/runs/<time>-<sha>/results.json)"),
                       args->out);
  add_record_options(*command, args->record);
  add_report_options(*command, args->reports);
  command->callback([args, command, &exit_code] {
    exit_code = run_command(*args, console_of(*command));
  });
}

}  // namespace raygate::cli

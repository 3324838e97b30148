// `raygate run`: measure one revision of a tracer against the baseline on a suite and write the
// results document. Options -> a run request -> the pipeline (pipeline/run_measurement.h:
// build, then per scene runs, ratios, image checks, document rewritten) -> summary, then
// pipeline/publish.h: store, gate, reports. Exit 0 measured and images pass, 1 an image check
// failed, 3 a scene could not be measured (the document says which and why).
#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/measure_options.h"
#include "cli/report_options.h"
#include "cli/subcommand.h"
#include "core/format.h"
#include "pipeline/terminal_progress.h"
#include "pipeline/run_measurement.h"
#include "runner/baseline_tool.h"

namespace raygate::cli {
namespace {

struct RunArgs {
  MeasureArgs measure;
  std::string rev = "HEAD";
  std::string worktree;
  std::string out;
  PublishOptions publish;  // --store, --no-store, --branch, --report, --format
};

int run_command(const RunArgs& args, const Console& console) {
  const MeasureContext context = load_measure_context(args.measure);
  check_publish_targets(args.publish, args.out, "--output", context.input_files);
  const BaselineTool baseline(context.tools.baseline);
  const RunTree tree =
      locate_run_tree(args.measure.repo, args.rev, args.worktree, context.cache_dir);
  TerminalIo terminal(console.quiet(), is_terminal(stderr));
  const MeasuredDocument measured =
      measure_run({context, baseline, tree.repository, tree.worktree, args.out}, terminal.io);
  const ResultsDocument& document = measured.document;
  if (const auto score = document.scores.find(Role::tracer); score != document.scores.end()) {
    console.info(
        fmt::format("suite score (geometric mean of normalized ratios): {:.3f} [{:.3f}, "
                    "{:.3f}] over {}",
                    score->second.score, score->second.interval.lower, score->second.interval.upper,
                    count_text(score->second.scenes, "scene")));
  }
  return publish_measured(measured, args.publish, context.cache_dir, context.policy, console);
}

}  // namespace

void add_run_command(CLI::App& command, int& exit_code) {
  RunArgs& args = bind_command<RunArgs>(command, run_command, exit_code);
  add_measure_options(command, args.measure);
  add_shard_options(command, args.measure);
  command.add_option("--rev", args.rev, "revision to measure (branch, tag, sha, HEAD~3, ...)")
      ->capture_default_str();
  command.add_option("--worktree", args.worktree,
                     "measure this directory as it is, uncommitted changes included (not --repo)");
  add_publish_options(command, args.out,
                      "results document (default: <cache-dir>/runs/<time>-<sha>/results.json)",
                      args.publish);
}

}  // namespace raygate::cli

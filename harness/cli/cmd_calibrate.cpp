// `raygate calibrate`: size a suite to a tracer, so that each render takes about the target
// seconds and a compare of a slow tracer fits a CI job (docs/calibrate.md). Options -> a
// calibrate request -> the pipeline (pipeline/calibrate.h: build, time each scene at two
// resolutions, write the suite file). Exit 0 written, 2 bad options or suite, 3 the tracer
// could not be built or run.
#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/measure_options.h"
#include "cli/subcommand.h"
#include "pipeline/terminal_progress.h"
#include "pipeline/calibrate.h"
#include "pipeline/measure_options.h"
#include "pipeline/revision_setup.h"
#include "runner/baseline_tool.h"

namespace raygate::cli {
namespace {

struct CalibrateArgs {
  MeasureOptions measure;
  std::string rev = "HEAD";
  std::string worktree;
  double target_seconds = 0.0;
  std::size_t runs = 3;  // one render a size, on a busy runner, once chose 16x16 (calibrate.md)
  int min_side = 16;
  std::string name;
  std::string out;
};

int calibrate_command(const CalibrateArgs& args, const Console& console) {
  const MeasureContext context = load_measure_context(args.measure);
  const BaselineTool baseline(context.tools.baseline);
  const RunTree tree =
      locate_run_tree(args.measure.repo, args.rev, args.worktree, context.cache_dir);
  const CalibrateRequest request{
      context,   baseline,      tree.repository, tree.worktree, args.target_seconds,
      args.runs, args.min_side, args.name,       args.out};
  check_calibrate_request(request);  // before the build
  TerminalIo terminal(console.quiet(), is_terminal(stderr));
  const Calibration calibration = calibrate_suite(request, terminal.io);
  console.info(calibration_summary(calibration, args.target_seconds));
  return 0;
}

}  // namespace

void add_calibrate_command(CLI::App& command, int& exit_code) {
  CalibrateArgs& args = bind_command<CalibrateArgs>(command, calibrate_command, exit_code);
  add_tracer_options(command, args.measure);
  command.add_option("--rev", args.rev, "revision to time")->capture_default_str();
  command.add_option("--worktree", args.worktree, "time this directory as it is (not --repo)");
  add_bounded_option(command, "--target-seconds", args.target_seconds, kMinTargetSeconds,
                     kMaxTargetSeconds, "wall seconds one render of each scene should take")
      ->required();
  add_bounded_option(command, "--runs", args.runs, 1, 20,
                     "renders at each of the two sizes timed; the fastest is kept")
      ->capture_default_str();
  add_bounded_option(command, "--min-side", args.min_side, 1, 4096,
                     "no calibrated picture side below this many pixels");
  command.add_option("--name", args.name, "the written suite's name (default: <suite>-<adapter>)");
  command
      .add_option("-o,--output", args.out,
                  "the suite file to write (.json), e.g. beside the adapter")
      ->required();
}

}  // namespace raygate::cli

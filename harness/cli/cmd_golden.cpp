// `raygate golden verify | bless`: the baseline's golden image of every suite scene, in
// golden/raygate-baseline/ (compare/golden.h says whom they judge). verify re-renders and demands
// identical pixels (the baseline is deterministic); bless rewrites only the scenes named (or all).
// `--from-run RESULTS.json`: a foreign tracer's images from a run instead, in golden/<adapter>/
// (docs/gate.md); for "images": "monte-carlo" the mean and variance of all its runs' images
// (docs/monte-carlo-images.md).
#include <fmt/core.h>

#include "cli/commands.h"
#include "cli/subcommand.h"
#include "pipeline/terminal_progress.h"
#include "pipeline/golden_commands.h"

namespace raygate::cli {
namespace {

// The per-scene lines are the results: plain, on standard output.
int run_verify(const GoldenOptions& options) {
  TerminalProgress lines(stdout, false);
  const GoldenOutcome outcome = verify_goldens(options, lines);
  fmt::print("{}\n", outcome.summary);
  return to_int(outcome.exit_code);
}

int run_bless(const GoldenOptions& options) {
  TerminalProgress lines(stdout, false);
  bless_goldens(options, lines);
  return 0;
}

// verify and bless take the same options; only what --from-run does differs.
void add_golden_subcommand(CLI::App& golden, const std::string& name, const std::string& help,
                           const std::string& from_run_help, int (*run)(const GoldenOptions&),
                           int& exit_code) {
  const auto [cmd, args] = add_subcommand<GoldenOptions>(golden, name, help, run, exit_code);
  cmd->add_option("--suite", args->suite, "suite name or file (default ci; --from-run: the run's)");
  cmd->add_option("--golden-dir", args->golden_dir,
                  "golden directory (default: golden/raygate-baseline/, the baseline's)")
      ->check(run == run_bless ? writable_folder() : CLI::Validator());  // before bless renders
  cmd->add_option("--work-dir", args->work_dir, "where scenes, renders and evidence go")
      ->capture_default_str()
      ->check(writable_folder());
  cmd->add_option("--baseline", args->baseline,
                  "raygate-baseline to use (default: beside raygate)");
  cmd->add_option("scenes", args->scenes, "suite scene ids (default: all)");
  cmd->add_option("--from-run", args->from_run, from_run_help);
  cmd->add_option("--role", args->role,
                  "with --from-run: whose images (default tracer; head, base)");
}

}  // namespace

void add_golden_command(CLI::App& golden, int& exit_code) {
  golden.require_subcommand(1);
  add_golden_subcommand(
      golden, "verify",
      "render the baseline and demand identical pixels, or check a run's images (--from-run)",
      "check a tracer's images from this results document against its adapter's goldens (Monte "
      "Carlo adapters: within noise) instead of rendering the baseline",
      run_verify, exit_code);
  add_golden_subcommand(
      golden, "bless",
      "render the baseline and overwrite its goldens, or bless a run's images (--from-run)",
      "bless a tracer's images from this results document instead of rendering the baseline "
      "(default golden dir: golden/<adapter>/)",
      run_bless, exit_code);
}

}  // namespace raygate::cli

// `raygate golden verify | bless`: the baseline's golden image of every suite scene, in
// golden/raygate-baseline/ (compare/golden.h says whom they judge). verify
// re-renders and demands identical pixels (the baseline is deterministic); bless rewrites goldens
// only for the scenes named (or all), never as a side effect of anything else.
// `bless --from-run RESULTS.json` blesses a foreign tracer's images instead: the ones a run
// already made and checked, copied into golden/<adapter>/ (docs/gate.md); for an adapter with
// "images": "monte-carlo" the mean and variance of all its runs' images
// (docs/monte-carlo-images.md). `verify --from-run RESULTS.json` checks a run against them.
#include <fmt/core.h>

#include <memory>
#include <optional>

#include "cli/commands.h"
#include "cli/terminal_progress.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "pipeline/golden_images.h"

namespace raygate::cli {
namespace {

struct GoldenArgs {
  std::string suite = "ci";
  std::vector<std::string> scenes;
  std::string golden_dir;  // default: <data root>/golden/raygate-baseline (--from-run: /<adapter>)
  std::string work_dir = ".raygate/golden";
  std::string baseline;
  std::string from_run;       // bless: a results document whose tracer images become goldens
  std::string role = "tracer";  // bless --from-run: whose images ("tracer", "head", "base")
};

BaselineGoldens open_goldens(const GoldenArgs& args) {
  return open_baseline_goldens(args.suite, args.scenes, args.golden_dir, args.work_dir,
                               args.baseline);
}

BlessFromRun from_run_request(const GoldenArgs& args) {
  BlessFromRun request;
  request.results = std::filesystem::absolute(args.from_run);
  const std::optional<Role> role = parse_role(args.role);
  if (!role || *role == Role::baseline) {
    throw UsageError("--role: no such revision role '" + args.role + "' (tracer, base or head)");
  }
  request.role = *role;
  request.scene_ids = args.scenes;
  request.golden_dir = args.golden_dir;
  request.baseline = args.baseline;
  return request;
}

// verify --from-run: a tracer's run against its adapter's goldens (exact or within noise).
int run_verify_from_run(const GoldenArgs& args) {
  Progress lines(stdout, false);
  const GoldenVerification v = verify_goldens_from_run(
      from_run_request(args), std::filesystem::path(args.work_dir) / "evidence", lines);
  fmt::print("{} scenes: {} same, {} different, {} too noisy to tell, {} missing\n",
             v.identical + v.different + v.inconclusive + v.missing, v.identical, v.different,
             v.inconclusive, v.missing);
  if (v.different > 0) return to_int(ExitCode::regression);
  return v.missing > 0 ? to_int(ExitCode::usage) : 0;
}

int run_verify(const GoldenArgs& args) {
  if (!args.from_run.empty()) return run_verify_from_run(args);
  const BaselineGoldens goldens = open_goldens(args);
  Progress lines(stdout, false);  // the per-scene lines are the results: plain, on stdout
  const GoldenVerification v = verify_baseline_goldens(goldens, lines);
  fmt::print("{} scenes: {} identical, {} different, {} missing\n", goldens.selected.size(),
             v.identical, v.different, v.missing);
  if (v.missing > 0) return to_int(ExitCode::usage);
  return v.different > 0 ? to_int(ExitCode::regression) : 0;
}

int run_bless(const GoldenArgs& args) {
  Progress lines(stdout, false);
  if (args.from_run.empty()) {
    bless_baseline_goldens(open_goldens(args), lines);
  } else {
    bless_goldens_from_run(from_run_request(args), lines);
  }
  return 0;
}

// verify and bless take the same options; only what --from-run does differs.
void add_golden_subcommand(CLI::App& golden, const std::string& name, const std::string& help,
                           const std::string& from_run_help, int (*run)(const GoldenArgs&),
                           int& exit_code) {
  auto args = std::make_shared<GoldenArgs>();
  CLI::App* cmd = golden.add_subcommand(name, help);
  cmd->add_option("--suite", args->suite, "Suite name or file")->capture_default_str();
  cmd->add_option("--golden-dir", args->golden_dir,
                  "Golden directory (default: golden/raygate-baseline/, the baseline's)");
  cmd->add_option("--work-dir", args->work_dir, "Where scenes, renders and evidence go")
      ->capture_default_str();
  cmd->add_option("--baseline", args->baseline, "raygate-baseline to use (default: beside raygate)");
  cmd->add_option("scenes", args->scenes, "Suite scene ids (default: all)");
  cmd->add_option("--from-run", args->from_run, from_run_help);
  cmd->add_option("--role", args->role, "With --from-run: whose images (tracer, head, base)")
      ->capture_default_str();
  cmd->callback([args, run, &exit_code] { exit_code = run(*args); });
}

}  // namespace

void add_golden_command(CLI::App& app, int& exit_code) {
  CLI::App* golden = app.add_subcommand("golden", "Verify or bless the baseline's golden images");
  golden->require_subcommand(1);
  add_golden_subcommand(*golden, "verify", "Re-render and demand identical pixels",
                        "Check a tracer's images from this results document against its "
                        "adapter's goldens (Monte Carlo adapters: within noise) instead of "
                        "rendering the baseline",
                        run_verify, exit_code);
  add_golden_subcommand(*golden, "bless", "Re-render and overwrite goldens (on request only)",
                        "Bless a tracer's images from this results document instead of "
                        "rendering the baseline (default golden dir: golden/<adapter>/)",
                        run_bless, exit_code);
}

}  // namespace raygate::cli

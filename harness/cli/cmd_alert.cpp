// `raygate alert`: judges what landed on a branch against its history. Each series of the
// store (one per repository, adapter, suite, scene settings, timing and baseline) over its last
// N commits is searched for change points (alert/); a series whose newest change point is a
// slowdown beyond the policy's limit is in alert, and the suspected commit range is named. Exit
// 1 when a series is in alert (--on-regression fail, the default), 0 with annotate; 2 usage.
#include "cli/commands.h"
#include "cli/console.h"
#include "cli/store_options.h"
#include "cli/subcommand.h"
#include "pipeline/store_commands.h"

namespace raygate::cli {
namespace {

struct AlertArgs {
  AlertRequest request = [] {
    AlertRequest r;
    r.store = kDefaultStorePath;
    r.query.last_commits = 30;  // enough for a change point with history on both sides
    return r;
  }();
  std::string on_regression = "fail";
  std::string format;
};

int alert_command(const AlertArgs& args, const Console& console) {
  AlertRequest request = args.request;
  request.action = parse_alert_action(args.on_regression);
  const AlertJudgement judgement =
      judge_store_history(request, [&console](const std::string& line) { console.info(line); });
  print_result(
      args.format, [&] { return alert_json(judgement, request.detection); },
      [&] { return alert_text(judgement); });
  return judgement.exit_code();
}

}  // namespace

void add_alert_command(CLI::App& command, int& exit_code) {
  AlertArgs& args = bind_command<AlertArgs>(command, alert_command, exit_code);
  add_store_option(command, args.request.store, kDefaultStorePath);
  add_history_filters(command, args.request.query);
  add_bounded_option(command, "--last", args.request.query.last_commits, 2, 100000,
                     "the newest N commits are the history judged");
  command
      .add_option("--policy", args.request.policy,
                  "gate policy file: each scene's max_slowdown is its alert limit")
      ->check(CLI::ExistingFile);
  command
      .add_option("--on-regression", args.on_regression,
                  "fail: exit 1 when a series is in alert; annotate: report it, exit 0")
      ->check(CLI::IsMember({"fail", "annotate"}))
      ->capture_default_str();
  add_bounded_option(command, "--min-segment", args.request.detection.min_segment, 1, 1000,
                     "commits needed on each side of a change point");
  add_bounded_option(command, "--permutations", args.request.detection.permutations, 9, 100000,
                     "random orders of the series for the significance test");
  add_bounded_option(command, "--significance", args.request.detection.significance, 0.0001, 0.5,
                     "a change point needs a permutation p-value below this");
  add_bounded_option(command, "--seed", args.request.detection.seed, std::uint64_t{0},
                     std::uint64_t{1} << 53, "seed of the permutations");
  add_format_option(command, args.format, {"text", "json"});
}

}  // namespace raygate::cli

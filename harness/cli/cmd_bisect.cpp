// `raygate bisect`: options -> a bisect request (pipeline/bisect.h) -> its steps as they come and
// the answer. Exit 0 found, 2 the bad end is not worse, 3 it (or the range) could not be measured.
#include <fmt/core.h>

#include <memory>

#include "cli/commands.h"
#include "cli/measure_options.h"
#include "cli/terminal_io.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "pipeline/bisect.h"

namespace raygate::cli {
namespace {

struct BisectArgs {
  MeasureArgs measure;
  std::string good;
  std::string bad;
  std::string metric = "ratio";  // ratio | image
};

int report_bisect(const BisectResult& result) {
  switch (result.outcome) {
    case BisectOutcome::bad_not_worse:
    case BisectOutcome::bad_unmeasurable:
      fmt::print("{} is not worse than {} on this scene; nothing to bisect\n",
                 result.first_bad.short_sha, result.good_short_sha);
      return to_int(result.outcome == BisectOutcome::bad_unmeasurable ? ExitCode::infrastructure
                                                                      : ExitCode::usage);
    case BisectOutcome::hidden_by_skips:
      fmt::print("the first bad commit is {} or one of the {} commits before it that could not "
                 "be measured\n",
                 result.first_bad.short_sha, result.unmeasured);
      return to_int(ExitCode::infrastructure);
    case BisectOutcome::found: break;
  }
  const Revision& first_bad = result.first_bad;
  fmt::print("first bad commit: {} {} ({}, {})\n", first_bad.sha, first_bad.subject,
             first_bad.author, first_bad.commit_time);
  return to_int(ExitCode::pass);
}

int bisect_command(const BisectArgs& args) {
  if (args.measure.scenes.size() != 1) {
    throw UsageError("bisect follows one scene: pass exactly one --scene");
  }
  const MeasureContext context = load_measure_context(args.measure);
  const BaselineTool baseline(context.tools.baseline);
  const Repository repository = Repository::open(args.measure.repo, context.cache_dir);
  const BisectRequest request{context, baseline, repository, args.good, args.bad,
                              args.metric == "image" ? BisectMetric::image : BisectMetric::ratio};
  TerminalIo terminal;
  return report_bisect(bisect(request, terminal.io));
}

}  // namespace

void add_bisect_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<BisectArgs>();
  CLI::App* command = app.add_subcommand(
      "bisect", "find the first commit that made a scene slower (or its image wrong)");
  add_measure_options(*command, args->measure);
  command->add_option("--good", args->good, "a revision without the problem")->required();
  command->add_option("--bad", args->bad, "a later revision with it")->required();
  command->add_option("--metric", args->metric, "ratio: a slowdown beyond the policy; image: an "
                      "image that differs from the good commit's")
      ->check(CLI::IsMember({"ratio", "image"}))
      ->capture_default_str();
  command->callback([args, &exit_code] { exit_code = bisect_command(*args); });
}

}  // namespace raygate::cli

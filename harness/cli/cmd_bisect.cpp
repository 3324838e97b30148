// `raygate bisect`: options -> a bisect request (pipeline/bisect.h) -> its steps as they come
// (standard error) and the answer (standard output: text, or with --format json one object with
// every step). Exit 0 found, 2 the bad end is not worse or the range holds no commits (the
// same commit twice, good newer than bad, unrelated ends), 3 it (or the range) could not be
// measured.
#include <fmt/core.h>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/measure_options.h"
#include "cli/subcommand.h"
#include "pipeline/terminal_progress.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/sanitize.h"
#include "pipeline/bisect_answer.h"

namespace raygate::cli {
namespace {

struct BisectArgs {
  MeasureArgs measure;
  std::string good;
  std::string bad;
  std::string metric = "ratio";  // ratio | image
  std::string format;            // text | json
  bool explain = false;          // --explain: profile REGRESSED steps (pipeline/explain_stage.h)
};

// The answer on standard output: text, or the whole bisection as JSON.
int answer(const BisectArgs& args, const std::string& scene, const BisectResult& result) {
  if (args.format == "json") {
    const nlohmann::json j = bisect_json(result, {scene, args.metric, args.bad});
    fmt::print("{}\n", j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace));
  } else {
    fmt::print("{}", terminal_text(bisect_text(result)));  // subjects are their authors' text
  }
  return to_int(bisect_exit_code(result));
}

int bisect_command(const BisectArgs& args, const Console& console) {
  if (args.measure.scenes.size() != 1) {
    throw UsageError("bisect follows one scene: pass exactly one --scene");
  }
  MeasureContext context = load_measure_context(args.measure);
  context.explain = args.explain;
  const BaselineTool baseline(context.tools.baseline);
  const Repository repository = Repository::open(args.measure.repo, context.cache_dir);
  const BisectRequest request{
      context,   baseline, repository,
      args.good, args.bad, args.metric == "image" ? BisectMetric::image : BisectMetric::ratio};
  TerminalIo terminal(console.quiet(), is_terminal(stderr));
  return answer(args, context.scenes.front().id, bisect(request, terminal.io));
}

}  // namespace

void add_bisect_command(CLI::App& command, int& exit_code) {
  BisectArgs& args = bind_command<BisectArgs>(command, bisect_command, exit_code);
  add_change_measure_options(command, args.measure);
  command.add_option("--good", args.good, "a revision without the problem")->required();
  command.add_option("--bad", args.bad, "a later revision with it")->required();
  command
      .add_option("--metric", args.metric,
                  "ratio: a slowdown beyond the policy; image: an "
                  "image that differs from the good commit's")
      ->check(CLI::IsMember({"ratio", "image"}))
      ->capture_default_str();
  command.add_flag("--explain", args.explain,
                   "profile each REGRESSED step's two revisions once under valgrind's callgrind "
                   "and end with where the culprit's time went (sim mode explains from its own "
                   "cachegrind files without it)");
  add_format_option(command, args.format, {"text", "json"});
}

}  // namespace raygate::cli

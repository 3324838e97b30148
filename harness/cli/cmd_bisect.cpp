// `raygate bisect`: options -> a bisect request (pipeline/bisect.h) -> its steps as they come
// (standard error) and the answer (standard output: text, or with --format json one object with
// every step). Exit 0 found, 2 the bad end is not worse or the range holds no commits (the
// same commit twice, good newer than bad, unrelated ends), 3 it (or the range) could not be
// measured.
#include <fmt/core.h>

#include <memory>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/console.h"
#include "cli/measure_options.h"
#include "cli/terminal_io.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "core/sanitize.h"
#include "pipeline/bisect.h"

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

nlohmann::json revision_json(const Revision& r) {
  return {{"sha", r.sha}, {"short_sha", r.short_sha}, {"subject", r.subject},
          {"author", r.author}, {"commit_time", r.commit_time}};
}

nlohmann::json step_json(const BisectStepRecord& step) {
  nlohmann::json j = revision_json(step.candidate);
  j["outcome"] = std::string(to_string(step.step));
  if (!step.reason.empty()) j["reason"] = step.reason;
  if (step.change) {
    j["change"] = step.change->change;
    j["change_interval"] = {step.change->change_interval.lower,
                            step.change->change_interval.upper};
    j["verdict"] = step.verdict ? std::string(to_string(*step.verdict)) : std::string();
    j["rounds"] = step.change->rounds;
  }
  return j;
}

ExitCode exit_code_of(const BisectResult& result) {
  switch (result.outcome) {
    case BisectOutcome::found: return ExitCode::pass;
    case BisectOutcome::bad_not_worse: return ExitCode::usage;
    case BisectOutcome::bad_unmeasurable:
    case BisectOutcome::hidden_by_skips: break;
  }
  return ExitCode::infrastructure;
}

std::string answer_text(const BisectResult& result) {
  const Revision& first_bad = result.first_bad;
  switch (result.outcome) {
    case BisectOutcome::bad_not_worse:
    case BisectOutcome::bad_unmeasurable:
      return fmt::format("{} is not worse than {} on this scene; nothing to bisect",
                         first_bad.short_sha, result.good.short_sha);
    case BisectOutcome::hidden_by_skips:
      return fmt::format("the first bad commit is {} or one of the {} commits before it that "
                         "could not be measured",
                         first_bad.short_sha, result.unmeasured);
    case BisectOutcome::found: break;
  }
  return fmt::format("first bad commit: {} {} ({}, {})", first_bad.sha, first_bad.subject,
                     first_bad.author, first_bad.commit_time);
}

nlohmann::json answer_json(const BisectResult& result) {
  switch (result.outcome) {
    case BisectOutcome::bad_not_worse:
    case BisectOutcome::bad_unmeasurable:
      return {{"kind", "not_worse"}, {"bad", revision_json(result.first_bad)}};
    case BisectOutcome::hidden_by_skips:
      return {{"kind", "range"},
              {"first_bad", revision_json(result.first_bad)},
              {"unmeasured_before", result.unmeasured}};
    case BisectOutcome::found: break;
  }
  return {{"kind", "first_bad"}, {"first_bad", revision_json(result.first_bad)}};
}

// The answer, with the merge note under it when the first bad commit is a merge.
nlohmann::json result_json(const BisectResult& result) {
  nlohmann::json j = answer_json(result);
  if (!result.merge_note.empty()) j["note"] = result.merge_note;
  return j;
}

// Where the first bad commit's time went (issue 27): its own step's explanation, when it has one.
const Explanation* culprit_explanation(const BisectResult& result) {
  if (result.outcome != BisectOutcome::found) return nullptr;
  for (const BisectStepRecord& step : result.steps) {
    if (step.candidate.sha == result.first_bad.sha && step.explanation) return &*step.explanation;
  }
  return nullptr;
}

// The answer on standard output: text, or the whole bisection as JSON.
int answer(const BisectArgs& args, const std::string& scene, const BisectResult& result) {
  const ExitCode code = exit_code_of(result);
  if (args.format == "json") {
    nlohmann::json steps = nlohmann::json::array();
    for (const BisectStepRecord& step : result.steps) steps.push_back(step_json(step));
    nlohmann::json j = {{"scene", scene},          {"metric", args.metric},
                        {"good", result.good.sha}, {"bad", args.bad},
                        {"candidates", result.candidates}, {"steps", steps},
                        {"result", result_json(result)}, {"exit_code", to_int(code)}};
    if (const Explanation* why = culprit_explanation(result)) {
      j["result"]["explanation"] = *why;
    }
    fmt::print("{}\n", j.dump(1, ' ', false, nlohmann::json::error_handler_t::replace));
  } else {
    std::string text = answer_text(result) + "\n";
    if (!result.merge_note.empty()) text += "note: " + result.merge_note + "\n";
    if (const Explanation* why = culprit_explanation(result)) {
      text += "the culprit against the good end, ";
      for (const std::string& line : explanation_lines(*why, 5)) text += line + "\n";
    }
    fmt::print("{}", terminal_text(text));  // the subject is the commit author's text
  }
  return to_int(code);
}

int bisect_command(const BisectArgs& args, const Console& console) {
  if (args.measure.scenes.size() != 1) {
    throw UsageError("bisect follows one scene: pass exactly one --scene");
  }
  MeasureContext context = load_measure_context(args.measure);
  context.explain = args.explain;
  const BaselineTool baseline(context.tools.baseline);
  const Repository repository = Repository::open(args.measure.repo, context.cache_dir);
  const BisectRequest request{context, baseline, repository, args.good, args.bad,
                              args.metric == "image" ? BisectMetric::image : BisectMetric::ratio};
  TerminalIo terminal(console);
  return answer(args, context.scenes.front().id, bisect(request, terminal.io));
}

}  // namespace

void add_bisect_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<BisectArgs>();
  args->measure.stopping = change_stopping_policy();
  args->measure.baseline_rounds = kChangeBaselineRounds;
  CLI::App* command = app.add_subcommand(
      "bisect", "find the first commit that made a scene slower (or its image wrong)");
  add_measure_options(*command, args->measure);
  add_baseline_rounds_option(*command, args->measure);
  command->add_option("--good", args->good, "a revision without the problem")->required();
  command->add_option("--bad", args->bad, "a later revision with it")->required();
  command->add_option("--metric", args->metric, "ratio: a slowdown beyond the policy; image: an "
                      "image that differs from the good commit's")
      ->check(CLI::IsMember({"ratio", "image"}))
      ->capture_default_str();
  command->add_flag("--explain", args->explain,
                    "profile each REGRESSED step's two revisions once under cachegrind and end "
                    "with where the culprit's time went (sim mode explains without it)");
  add_format_option(*command, args->format, {"text", "json"});
  command->callback([args, command, &exit_code] {
    exit_code = bisect_command(*args, console_of(*command));
  });
}

}  // namespace raygate::cli

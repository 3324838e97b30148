// `raygate bisect`: the first commit between a good and a bad revision (first-parent history)
// that made one scene slower or its image wrong. Each step measures the candidate against the
// good commit in the same job (compare_session), so every decision is a paired measurement, not
// a comparison of numbers taken at different times. A commit that does not build is skipped,
// as `git bisect skip` would; if skips hide the answer, the range that holds it is printed.
// Each step is said on standard error; the answer goes to standard output, as text or, with
// --format json, as one JSON object with every step.
#include <fmt/core.h>

#include <algorithm>
#include <memory>
#include <optional>

#include "checkout/repository.h"
#include "cli/commands.h"
#include "cli/compare_session.h"
#include "cli/console.h"
#include "cli/revision_setup.h"
#include "core/error.h"
#include "core/exit_codes.h"
#include "measure/change.h"

namespace raygate::cli {
namespace {

struct BisectArgs {
  MeasureArgs measure;
  std::string good;
  std::string bad;
  std::string metric = "ratio";  // ratio | image
  std::string format;            // text | json
};

enum class Step { good, bad, skipped };

std::string_view step_name(Step step) {
  return step == Step::good ? "good" : step == Step::bad ? "bad" : "skipped";
}

nlohmann::json revision_json(const Revision& r) {
  return {{"sha", r.sha}, {"short_sha", r.short_sha}, {"subject", r.subject},
          {"author", r.author}, {"commit_time", r.commit_time}};
}

// One judged commit, for --format json.
nlohmann::json step_json(const Revision& candidate, Step step, const SceneResult* scene,
                         const std::string& why) {
  nlohmann::json j = revision_json(candidate);
  j["outcome"] = step_name(step);
  if (!why.empty()) j["reason"] = why;
  if (scene != nullptr && scene->change) {
    j["change"] = scene->change->change;
    j["change_interval"] = {scene->change->change_interval.lower,
                            scene->change->change_interval.upper};
    j["verdict"] = scene->change_verdict;
  }
  return j;
}

struct Bisector {
  const BisectArgs& args;
  const MeasureContext& context;
  const BaselineTool& baseline;
  const Repository& repository;
  const Console& console;
  Worktree good;
  // The slowdown that separates good from bad. The bad end is judged against the policy's limit;
  // after that a step is bad when its change is above half of what the bad end's surely is (the
  // lower end of its CI: its estimate alone once came out +27% for a +11% culprit, and the
  // split at +13.6% called the culprit good). So a commit with a small unrelated change (+1%
  // where the culprit made +10%) is not called the culprit by a median straying over 3%.
  std::optional<double> split;
  nlohmann::json steps = nlohmann::json::array();  // every judged commit, in the order judged

  // Measures `candidate` against the good commit on the one scene and says which side it is on.
  Step judge(const Revision& candidate) {
    const Worktree tree = repository.materialize(candidate);
    const BuildRecord build = build_revision(tree, context, baseline.source_hash(), context.jobs);
    if (!build.success) {
      console.info(fmt::format("  {} {}: does not build ({}), skipped", candidate.short_sha,
                               candidate.subject, build.failure));
      steps.push_back(step_json(candidate, Step::skipped, nullptr, "does not build: " + build.failure));
      return Step::skipped;
    }
    const ResultsDocument document =
        measure_compare({context, baseline, repository.location(), good, tree, {}}, nullptr);
    const SceneResult& scene = document.scenes.front();
    if (scene.runs.failed()) {
      console.info(fmt::format("  {} {}: could not be measured ({}), skipped", candidate.short_sha,
                               candidate.subject, scene.runs.failed_run->failure));
      steps.push_back(step_json(candidate, Step::skipped, &scene,
                                "could not be measured: " + scene.runs.failed_run->failure));
      return Step::skipped;
    }
    const bool bad = args.metric == "image" ? image_failed(scene) : speed_regressed(scene);
    console.info(fmt::format("  {} {}: {} -> {}", candidate.short_sha, candidate.subject,
                             describe(scene), bad ? "bad" : "good"));
    steps.push_back(step_json(candidate, bad ? Step::bad : Step::good, &scene, ""));
    if (bad && !split && scene.change) {
      const double limit = context.policy.for_scene(scene.entry.id).max_slowdown;
      split = std::max(limit, scene.change->change_interval.lower / 2);
      if (args.metric == "ratio") {
        console.info(fmt::format("  later steps are bad above {:+.1f}% (half the lower end of "
                                 "this one's CI, or the limit)",
                                 100 * *split));
      }
    }
    return bad ? Step::bad : Step::good;
  }

  bool speed_regressed(const SceneResult& scene) const {
    // An INCONCLUSIVE step is decided by its point estimate against the limit: bisect must
    // choose a side, and the printed numbers show how close the call was.
    const double limit = split.value_or(context.policy.for_scene(scene.entry.id).max_slowdown);
    const ChangeVerdict verdict = classify_change(*scene.change, limit);
    return verdict == ChangeVerdict::regressed ||
           (verdict == ChangeVerdict::inconclusive && scene.change->change > limit);
  }

  static bool image_failed(const SceneResult& scene) {
    for (const ImageCheck& check : scene.images) {
      if (check.reference == "base" && check.verdict == "fail") return true;
    }
    return false;
  }

  static std::string describe(const SceneResult& scene) {
    const ChangeSummary& c = *scene.change;
    return fmt::format("{:+.1f}% [{:+.1f}%, {:+.1f}%] {}", 100 * c.change,
                       100 * c.change_interval.lower, 100 * c.change_interval.upper,
                       scene.change_verdict);
  }
};

// The untested index in (low, high) nearest the middle, or nullopt.
std::optional<std::size_t> next_probe(const std::vector<std::optional<Step>>& steps, long low,
                                      long high) {
  const long middle = low + (high - low) / 2;
  for (long offset = 0; offset < high - low; ++offset) {
    for (const long index : {middle - offset, middle + offset}) {
      if (index > low && index < high && !steps[static_cast<std::size_t>(index)]) {
        return static_cast<std::size_t>(index);
      }
    }
  }
  return std::nullopt;
}

// The answer on standard output: text, or the whole bisection as JSON.
int answer(const BisectArgs& args, const Bisector& bisector, const std::string& scene,
           std::size_t candidates, const std::string& text, const nlohmann::json& found,
           ExitCode code) {
  if (args.format == "json") {
    const nlohmann::json j = {{"scene", scene},          {"metric", args.metric},
                              {"good", bisector.good.sha}, {"bad", args.bad},
                              {"candidates", candidates}, {"steps", bisector.steps},
                              {"result", found},          {"exit_code", to_int(code)}};
    fmt::print("{}\n", j.dump(1));
  } else {
    fmt::print("{}\n", text);
  }
  return to_int(code);
}

int bisect_command(const BisectArgs& args, const Console& console) {
  if (args.measure.scenes.size() != 1) {
    throw UsageError("bisect follows one scene: pass exactly one --scene");
  }
  MeasureContext context = load_measure_context(args.measure);
  context.quiet = console.quiet();
  const BaselineTool baseline(context.tools.baseline);
  const Repository repository = Repository::open(args.measure.repo, context.cache_dir);
  const std::vector<Revision> candidates = repository.first_parent_history(args.good, args.bad);
  Bisector bisector{args,    context, baseline, repository, console, repository.checkout(args.good),
                    std::nullopt, nlohmann::json::array()};
  const std::string scene = context.scenes.front().id;
  console.info(fmt::format("bisecting {} commits after {} on scene {} by {}", candidates.size(),
                           bisector.good.short_sha, scene, args.metric));

  std::vector<std::optional<Step>> steps(candidates.size());
  const std::size_t last = candidates.size() - 1;
  steps[last] = bisector.judge(candidates[last]);
  if (steps[last] != Step::bad) {
    return answer(args, bisector, scene, candidates.size(),
                  fmt::format("{} is not worse than {} on this scene; nothing to bisect",
                              candidates[last].short_sha, bisector.good.short_sha),
                  {{"kind", "not_worse"}, {"bad", revision_json(candidates[last])}},
                  steps[last] == Step::skipped ? ExitCode::infrastructure : ExitCode::usage);
  }
  long low = -1;  // index of the last known good (-1: the good revision itself)
  long high = static_cast<long>(last);  // index of the first known bad
  while (const std::optional<std::size_t> probe = next_probe(steps, low, high)) {
    steps[*probe] = bisector.judge(candidates[*probe]);
    if (steps[*probe] == Step::good) low = static_cast<long>(*probe);
    if (steps[*probe] == Step::bad) high = static_cast<long>(*probe);
  }
  const Revision& first_bad = candidates[static_cast<std::size_t>(high)];
  if (high - low > 1) {
    return answer(args, bisector, scene, candidates.size(),
                  fmt::format("the first bad commit is {} or one of the {} commits before it "
                              "that could not be measured",
                              first_bad.short_sha, high - low - 1),
                  {{"kind", "range"},
                   {"first_bad", revision_json(first_bad)},
                   {"unmeasured_before", high - low - 1}},
                  ExitCode::infrastructure);
  }
  return answer(args, bisector, scene, candidates.size(),
                fmt::format("first bad commit: {} {} ({}, {})", first_bad.sha, first_bad.subject,
                            first_bad.author, first_bad.commit_time),
                {{"kind", "first_bad"}, {"first_bad", revision_json(first_bad)}}, ExitCode::pass);
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
  add_format_option(*command, args->format, {"text", "json"});
  command->callback([args, command, &exit_code] {
    exit_code = bisect_command(*args, console_of(*command));
  });
}

}  // namespace raygate::cli

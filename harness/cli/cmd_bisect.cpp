// `raygate bisect`: the first commit between a good and a bad revision (first-parent history)
// that made one scene slower or its image wrong. Each step measures the candidate against the
// good commit in the same job (compare_session), so every decision is a paired measurement, not
// a comparison of numbers taken at different times. A commit that does not build is skipped,
// as `git bisect skip` would; if skips hide the answer, the range that holds it is printed.
#include <fmt/core.h>

#include <algorithm>
#include <memory>
#include <optional>

#include "checkout/repository.h"
#include "cli/commands.h"
#include "cli/compare_session.h"
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
};

enum class Step { good, bad, skipped };

struct Bisector {
  const BisectArgs& args;
  const MeasureContext& context;
  const BaselineTool& baseline;
  const Repository& repository;
  Worktree good;
  // The slowdown that separates good from bad. The bad end is judged against the policy's limit;
  // after that a step is bad when its change is above half of what the bad end's surely is (the
  // lower end of its CI: its estimate alone once came out +27% for a +11% culprit, and the
  // split at +13.6% called the culprit good). So a commit with a small unrelated change (+1%
  // where the culprit made +10%) is not called the culprit by a median straying over 3%.
  std::optional<double> split;

  // Measures `candidate` against the good commit on the one scene and says which side it is on.
  Step judge(const Revision& candidate) {
    const Worktree tree = repository.materialize(candidate);
    const BuildRecord build = build_revision(tree, context, baseline.source_hash(), context.jobs);
    if (!build.success) {
      fmt::print("  {} {}: does not build ({}), skipped\n", candidate.short_sha, candidate.subject,
                 build.failure);
      return Step::skipped;
    }
    const ResultsDocument document =
        measure_compare({context, baseline, repository.location(), good, tree, {}}, nullptr);
    const SceneResult& scene = document.scenes.front();
    if (scene.runs.failed()) {
      fmt::print("  {} {}: could not be measured ({}), skipped\n", candidate.short_sha,
                 candidate.subject, scene.runs.failed_run->failure);
      return Step::skipped;
    }
    const bool bad = args.metric == "image" ? image_failed(scene) : speed_regressed(scene);
    fmt::print("  {} {}: {} -> {}\n", candidate.short_sha, candidate.subject, describe(scene),
               bad ? "bad" : "good");
    if (bad && !split && scene.change) {
      const double limit = context.policy.for_scene(scene.entry.id).max_slowdown;
      split = std::max(limit, scene.change->change_interval.lower / 2);
      if (args.metric == "ratio") {
        fmt::print("  later steps are bad above {:+.1f}% (half the lower end of this one's CI, "
                   "or the limit)\n",
                   100 * *split);
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

int bisect_command(const BisectArgs& args) {
  if (args.measure.scenes.size() != 1) {
    throw UsageError("bisect follows one scene: pass exactly one --scene");
  }
  const MeasureContext context = load_measure_context(args.measure);
  const BaselineTool baseline(context.tools.baseline);
  const Repository repository = Repository::open(args.measure.repo, context.cache_dir);
  const std::vector<Revision> candidates = repository.first_parent_history(args.good, args.bad);
  Bisector bisector{args, context, baseline, repository, repository.checkout(args.good),
                    std::nullopt};
  fmt::print("bisecting {} commits after {} on scene {} by {}\n", candidates.size(),
             bisector.good.short_sha, context.scenes.front().id, args.metric);

  std::vector<std::optional<Step>> steps(candidates.size());
  const std::size_t last = candidates.size() - 1;
  steps[last] = bisector.judge(candidates[last]);
  if (steps[last] != Step::bad) {
    fmt::print("{} is not worse than {} on this scene; nothing to bisect\n",
               candidates[last].short_sha, bisector.good.short_sha);
    return to_int(steps[last] == Step::skipped ? ExitCode::infrastructure : ExitCode::usage);
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
    fmt::print("the first bad commit is {} or one of the {} commits before it that could not be "
               "measured\n",
               first_bad.short_sha, high - low - 1);
    return to_int(ExitCode::infrastructure);
  }
  fmt::print("first bad commit: {} {} ({}, {})\n", first_bad.sha, first_bad.subject,
             first_bad.author, first_bad.commit_time);
  return to_int(ExitCode::pass);
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

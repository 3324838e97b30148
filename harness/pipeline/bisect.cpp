#include "pipeline/bisect.h"

#include <fmt/core.h>

#include <algorithm>

#include "core/error.h"
#include "measure/change.h"
#include "pipeline/compare_measurement.h"
#include "pipeline/revision_setup.h"

namespace raygate {

namespace {

// Measures candidates against the good commit on the one scene and says which side each is on.
struct Bisector {
  const BisectRequest& request;
  PipelineIo& io;
  Worktree good;
  std::optional<PreparedRevision> good_built;  // built at the first step, then reused
  // The slowdown that separates good from bad. The bad end is judged against the policy's limit;
  // after that a step is bad when its change is above half of what the bad end's surely is (the
  // lower end of its CI: its estimate alone once came out +27% for a +11% culprit, and the
  // split at +13.6% called the culprit good). So a commit with a small unrelated change (+1%
  // where the culprit made +10%) is not called the culprit by a median straying over 3%.
  std::optional<double> split;
  std::vector<BisectStepRecord> steps;

  BisectStep judge(const Revision& candidate) {
    BisectStepRecord record = judge_step(candidate);
    const BisectStep step = record.step;
    steps.push_back(std::move(record));
    return step;
  }

  BisectStepRecord judge_step(const Revision& candidate) {
    const MeasureContext& context = request.context;
    const Worktree tree = request.repository.materialize(candidate);
    const BuildRecord build =
        build_revision(tree, context, request.baseline.source_hash(), context.jobs, io.progress);
    if (!build.success) {
      io.progress.line(fmt::format("  {} {}: does not build ({}), skipped", candidate.short_sha,
                                   candidate.subject, build.failure));
      return {candidate, BisectStep::skipped, "does not build: " + build.failure, {}, {}, {}};
    }
    const std::string repository = request.repository.location();
    if (!good_built) {
      good_built = prepare_revision(Role::base, repository, good, context,
                                    request.baseline.source_hash(), context.jobs, io.progress);
    }
    const MeasuredDocument measured = measure_prepared_compare(
        {context, request.baseline, repository, good, tree, {}, false}, *good_built,
        prepared_revision(Role::head, repository, tree, context, build), io);
    const SceneResult& scene = measured.document.scenes.front();
    if (scene.runs.failed()) {
      io.progress.line(fmt::format("  {} {}: could not be measured ({}), skipped",
                                   candidate.short_sha, candidate.subject,
                                   scene.runs.failed_run->failure));
      return {candidate,
              BisectStep::skipped,
              "could not be measured: " + scene.runs.failed_run->failure,
              scene.change,
              verdict_of(scene),
              {}};
    }
    const bool bad =
        request.metric == BisectMetric::image ? image_failed(scene) : speed_regressed(scene);
    const bool undecided_end = request.metric == BisectMetric::ratio && steps.empty() &&
                               scene.change_verdict == ChangeVerdict::inconclusive;
    io.progress.line(fmt::format("  {} {}: {} -> {}", candidate.short_sha, candidate.subject,
                                 describe(scene),
                                 bad ? "bad" : (undecided_end ? "not shown worse" : "good")));
    if (bad && !split && scene.change) {
      const double limit = context.policy.for_scene(scene.entry.id).max_slowdown;
      split = std::max(limit, scene.change->change_interval.lower / 2);
      if (request.metric == BisectMetric::ratio) {
        io.progress.line(
            fmt::format("  later steps are bad above {:+.1f}% (half the lower end "
                        "of this one's CI, or the limit)",
                        100 * *split));
      }
    }
    return {candidate,
            bad ? BisectStep::bad : BisectStep::good,
            {},
            scene.change,
            verdict_of(scene),
            scene.explanation};
  }

  bool speed_regressed(const SceneResult& scene) const {
    const double limit =
        split.value_or(request.context.policy.for_scene(scene.entry.id).max_slowdown);
    return slower_step(*scene.change, limit, steps.empty());  // the bad end is judged first
  }

  static std::optional<ChangeVerdict> verdict_of(const SceneResult& scene) {
    if (!scene.change) return std::nullopt;
    return scene.change_verdict;
  }

  static bool image_failed(const SceneResult& scene) {
    for (const ImageCheck& check : scene.images) {
      if (check.reference == ImageReference::base && check.failed()) return true;
    }
    return false;
  }

  static std::string describe(const SceneResult& scene) {
    const ChangeSummary& c = *scene.change;
    return fmt::format("{:+.1f}% [{:+.1f}%, {:+.1f}%] {}", 100 * c.change,
                       100 * c.change_interval.lower, 100 * c.change_interval.upper,
                       to_string(scene.change_verdict));
  }
};

// The commits between the two ends, oldest first; a UsageError naming the commit when both
// ends are one commit (the same name twice, or a tag and its sha).
std::vector<Revision> candidates_of(const BisectRequest& request) {
  std::vector<Revision> candidates =
      request.repository.first_parent_history(request.good, request.bad);
  if (candidates.empty()) {
    const Revision same = request.repository.resolve(request.bad);
    throw UsageError(fmt::format(
        "--good '{}' and --bad '{}' are the same commit {} ({}): there is nothing between them to "
        "bisect; give --good a revision older than --bad",
        request.good, request.bad, same.short_sha, same.subject));
  }
  return candidates;
}

// Bisect follows first parents, so a merge found bad stands for every commit it merged: say
// which range to bisect next. Empty when `first_bad` is not a merge.
std::string merge_note(const Repository& repository, const Revision& first_bad) {
  const std::vector<std::string> parents = repository.parents(first_bad);
  if (parents.size() < 2) return "";
  const Revision side = repository.resolve(parents[1]);
  const std::optional<Revision> base = repository.merge_base(parents[0], parents[1]);
  if (base && base->sha == side.sha) return "";  // the merged side was already in: nothing new
  if (!base) {
    return fmt::format(
        "{} is a merge of a history unrelated to the good one ({}); its commits "
        "were not searched one by one",
        first_bad.short_sha, side.short_sha);
  }
  return fmt::format(
      "{} is a merge: the commits it merged were not searched one by one; to "
      "search them, bisect again with --good {} --bad {}",
      first_bad.short_sha, base->short_sha, side.short_sha);
}

// The untested index in (low, high) nearest the middle, or nullopt.
std::optional<std::size_t> next_probe(const std::vector<std::optional<BisectStep>>& steps, long low,
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

}  // namespace

std::string_view to_string(BisectStep step) {
  switch (step) {
    case BisectStep::good: return "good";
    case BisectStep::bad: return "bad";
    case BisectStep::skipped: break;
  }
  return "skipped";
}

bool slower_step(const ChangeSummary& change, double limit, bool bad_end) {
  // Between the ends, an INCONCLUSIVE step is decided by its point estimate: bisect must choose
  // a side, and the printed numbers show how close the call was.
  const ChangeVerdict verdict = classify_change(change, limit);
  if (verdict == ChangeVerdict::regressed) return true;
  return !bad_end && verdict == ChangeVerdict::inconclusive && change.change > limit;
}

BisectResult bisect_search(const std::vector<Revision>& candidates, const BisectJudge& judge) {
  // Nothing to search: the bad end would be candidates[-1] (a 0-commit range once crashed).
  if (candidates.empty()) throw UsageError("nothing to bisect: the range holds no commits");
  std::vector<std::optional<BisectStep>> steps(candidates.size());
  const std::size_t last = candidates.size() - 1;
  steps[last] = judge(candidates[last]);
  if (steps[last] != BisectStep::bad) {
    return {steps[last] == BisectStep::skipped ? BisectOutcome::bad_unmeasurable
                                               : BisectOutcome::bad_not_worse,
            candidates[last],
            0,
            {},
            candidates.size(),
            {},
            {}};
  }
  long low = -1;  // index of the last known good (-1: the good revision itself)
  long high = static_cast<long>(last);  // index of the first known bad
  while (const std::optional<std::size_t> probe = next_probe(steps, low, high)) {
    steps[*probe] = judge(candidates[*probe]);
    if (steps[*probe] == BisectStep::good) low = static_cast<long>(*probe);
    if (steps[*probe] == BisectStep::bad) high = static_cast<long>(*probe);
  }
  const Revision& first_bad = candidates[static_cast<std::size_t>(high)];
  if (high - low > 1) {
    return {BisectOutcome::hidden_by_skips,
            first_bad,
            static_cast<std::size_t>(high - low - 1),
            {},
            candidates.size(),
            {},
            {}};
  }
  return {BisectOutcome::found, first_bad, 0, {}, candidates.size(), {}, {}};
}

BisectResult bisect(const BisectRequest& request, PipelineIo& io) {
  const std::vector<Revision> candidates = candidates_of(request);
  Bisector bisector{request,      io,           request.repository.checkout(request.good),
                    std::nullopt, std::nullopt, {}};
  io.progress.line(fmt::format("bisecting {} commits after {} on scene {} by {}", candidates.size(),
                               bisector.good.short_sha, request.context.scenes.front().id,
                               request.metric == BisectMetric::image ? "image" : "ratio"));
  BisectResult result = bisect_search(
      candidates, [&](const Revision& candidate) { return bisector.judge(candidate); });
  result.good = bisector.good;
  result.metric = request.metric;
  result.steps = std::move(bisector.steps);
  if (result.outcome == BisectOutcome::found || result.outcome == BisectOutcome::hidden_by_skips) {
    result.merge_note = merge_note(request.repository, result.first_bad);
  }
  return result;
}

}  // namespace raygate

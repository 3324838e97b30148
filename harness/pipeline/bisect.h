// `raygate bisect`: the first commit between a good and a bad revision (first-parent history)
// that made one scene slower or its image wrong. Each step measures the candidate against the
// good commit in the same job (compare_measurement.h), so every decision is a paired
// measurement, not a comparison of numbers taken at different times. A commit that does not
// build is skipped, as `git bisect skip` would; if skips hide the answer, the result says which
// range holds it.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "checkout/repository.h"
#include "explain/explanation.h"
#include "measure/change.h"
#include "pipeline/measure_context.h"
#include "pipeline/pipeline_io.h"
#include "runner/baseline_tool.h"

namespace raygate {

enum class BisectMetric { ratio, image };

struct BisectRequest {
  const MeasureContext& context;  // exactly one scene
  const BaselineTool& baseline;
  const Repository& repository;
  std::string good;
  std::string bad;
  BisectMetric metric = BisectMetric::ratio;
};

enum class BisectStep { good, bad, skipped };

std::string_view to_string(BisectStep step);

// One judged commit, in the order judged (bisect --format json lists them).
struct BisectStepRecord {
  Revision candidate;
  BisectStep step = BisectStep::skipped;
  std::string reason;                    // skipped: why
  std::optional<ChangeSummary> change;   // measured: head (the candidate) against the good end
  std::optional<ChangeVerdict> verdict;  // of that change
  // Where that change's time went (sim mode, or --explain; explain/explanation.h), when the
  // step REGRESSED: the culprit's is what bisect ends with.
  std::optional<Explanation> explanation;
};

enum class BisectOutcome {
  found,             // first_bad is the first bad commit
  bad_not_worse,     // the bad end measured good: nothing to bisect
  bad_unmeasurable,  // the bad end did not build or could not be measured
  hidden_by_skips,   // first_bad, or one of the `unmeasured` commits before it
};

struct BisectResult {
  BisectOutcome outcome = BisectOutcome::found;
  Revision first_bad;          // the bad end itself unless found or hidden_by_skips
  std::size_t unmeasured = 0;  // hidden_by_skips: commits before first_bad that were skipped
  Worktree good;               // the good end, as the steps named it
  std::size_t candidates = 0;  // commits after the good end, up to the bad one
  std::vector<BisectStepRecord> steps;
  // found or hidden_by_skips with a merge as first_bad: the range its merged commits span, to
  // bisect next (bisect follows first parents); empty otherwise.
  std::string merge_note;
  BisectMetric metric = BisectMetric::ratio;  // what "bad" meant (the answer's words follow it)
};

// Decides one candidate (the real one builds and measures it; tests pass their own).
using BisectJudge = std::function<BisectStep(const Revision& candidate)>;

// The search over `candidates` (oldest first, the good revision excluded): the last one first,
// then the untested commit nearest the middle of the open range, until the range is one commit.
// UsageError when `candidates` is empty.
BisectResult bisect_search(const std::vector<Revision>& candidates, const BisectJudge& judge);

// Whether a step is bad by speed: regressed against `limit`. The bad end must be shown worse
// (REGRESSED); a step between the ends that stays INCONCLUSIVE is decided by its estimate against
// the limit, since bisect must choose a side (sweep 13: an undecided bad end named a culprit
// out of noise).
bool slower_step(const ChangeSummary& change, double limit, bool bad_end);

// Resolves the range, builds and measures each probed commit against the good one, and says
// each step through io.progress. A range without commits is a UsageError before anything is
// built: both ends one commit, the good end newer than the bad one, unrelated or diverged ends.
BisectResult bisect(const BisectRequest& request, PipelineIo& io);

}  // namespace raygate

#include "pipeline/bisect_answer.h"

#include <fmt/core.h>

namespace raygate {
namespace {

nlohmann::json revision_json(const Revision& r) {
  return {{"sha", r.sha},
          {"short_sha", r.short_sha},
          {"subject", r.subject},
          {"author", r.author},
          {"commit_time", r.commit_time}};
}

nlohmann::json step_json(const BisectStepRecord& step) {
  nlohmann::json j = revision_json(step.candidate);
  j["outcome"] = std::string(to_string(step.step));
  if (!step.reason.empty()) j["reason"] = step.reason;
  if (step.change) {
    j["change"] = step.change->change;
    j["change_interval"] = {step.change->change_interval.lower, step.change->change_interval.upper};
    j["verdict"] = step.verdict ? std::string(to_string(*step.verdict)) : std::string();
    j["rounds"] = step.change->rounds;
  }
  return j;
}

}  // namespace

ExitCode bisect_exit_code(const BisectResult& result) {
  switch (result.outcome) {
    case BisectOutcome::found: return ExitCode::pass;
    case BisectOutcome::bad_not_worse: return ExitCode::usage;
    case BisectOutcome::bad_unmeasurable:
    case BisectOutcome::hidden_by_skips: break;
  }
  return ExitCode::infrastructure;
}

namespace {

// The bad end's own step: what measuring it showed (or why it could not be measured).
const BisectStepRecord* bad_end_step(const BisectResult& result) {
  for (const BisectStepRecord& step : result.steps) {
    if (step.candidate.sha == result.first_bad.sha) return &step;
  }
  return nullptr;
}

// The bad end was judged good: shown not worse, or only not shown worse (INCONCLUSIVE, its
// point estimate under the limit), which is said as what it is.
std::string not_worse_text(const BisectResult& result) {
  if (result.metric == BisectMetric::image) {  // its speed is beside the point (a sweep)
    return fmt::format(
        "{}'s image is not shown to differ from {}'s on this scene; nothing to "
        "bisect by image",
        result.first_bad.short_sha, result.good.short_sha);
  }
  const BisectStepRecord* step = bad_end_step(result);
  if (step == nullptr || !step->change || step->verdict != ChangeVerdict::inconclusive) {
    return fmt::format("{} is not worse than {} on this scene; nothing to bisect",
                       result.first_bad.short_sha, result.good.short_sha);
  }
  const ChangeSummary& c = *step->change;
  return fmt::format(
      "could not tell whether {} is worse than {} on this scene ({:+.1f}% [{:+.1f}%, {:+.1f}%], "
      "INCONCLUSIVE): nothing to bisect until it is shown worse; measure longer "
      "(--max-minutes) or on a quieter runner",
      result.first_bad.short_sha, result.good.short_sha, 100.0 * c.change,
      100.0 * c.change_interval.lower, 100.0 * c.change_interval.upper);
}

std::string unmeasurable_text(const BisectResult& result) {
  const BisectStepRecord* step = bad_end_step(result);
  return fmt::format("{} could not be measured ({}); nothing to bisect", result.first_bad.short_sha,
                     step != nullptr && !step->reason.empty() ? step->reason
                                                              : "it did not build or run");
}

std::string answer_text(const BisectResult& result) {
  const Revision& first_bad = result.first_bad;
  switch (result.outcome) {
    case BisectOutcome::bad_not_worse: return not_worse_text(result);
    case BisectOutcome::bad_unmeasurable: return unmeasurable_text(result);
    case BisectOutcome::hidden_by_skips:
      return fmt::format(
          "the first bad commit is {} or one of the {} before it that could not be measured",
          first_bad.short_sha,
          result.unmeasured == 1 ? std::string("1 commit")
                                 : fmt::format("{} commits", result.unmeasured));
    case BisectOutcome::found: break;
  }
  return fmt::format("first bad commit: {} {} ({}, {})", first_bad.sha, first_bad.subject,
                     first_bad.author, first_bad.commit_time);
}

nlohmann::json answer_json(const BisectResult& result) {
  switch (result.outcome) {
    case BisectOutcome::bad_not_worse: {
      const BisectStepRecord* step = bad_end_step(result);
      const bool undecided = result.metric == BisectMetric::ratio && step != nullptr &&
                             step->verdict == ChangeVerdict::inconclusive;
      return {{"kind", undecided ? "not_shown_worse" : "not_worse"},
              {"bad", revision_json(result.first_bad)}};
    }
    case BisectOutcome::bad_unmeasurable: {
      const BisectStepRecord* step = bad_end_step(result);
      return {{"kind", "bad_unmeasurable"},
              {"bad", revision_json(result.first_bad)},
              {"reason", step != nullptr ? step->reason : std::string()}};
    }
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

}  // namespace

nlohmann::json bisect_json(const BisectResult& result, const BisectAnswerContext& context) {
  nlohmann::json steps = nlohmann::json::array();
  for (const BisectStepRecord& step : result.steps) steps.push_back(step_json(step));
  nlohmann::json j = {
      {"scene", context.scene},          {"metric", context.metric},
      {"good", result.good.sha},         {"bad", context.bad},
      {"candidates", result.candidates}, {"steps", steps},
      {"result", result_json(result)},   {"exit_code", to_int(bisect_exit_code(result))}};
  if (const Explanation* why = culprit_explanation(result)) j["result"]["explanation"] = *why;
  return j;
}

std::string bisect_text(const BisectResult& result) {
  std::string text = answer_text(result) + "\n";
  if (!result.merge_note.empty()) text += "note: " + result.merge_note + "\n";
  if (const Explanation* why = culprit_explanation(result)) {
    text += "the culprit against the good end, ";
    for (const std::string& line : explanation_lines(*why, 5)) text += line + "\n";
  }
  return text;
}

}  // namespace raygate

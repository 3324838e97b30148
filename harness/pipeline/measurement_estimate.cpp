#include "pipeline/measurement_estimate.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "core/domain.h"
#include "core/format.h"
#include "measure/confidence_sequence.h"
#include "pipeline/calibrate.h"

namespace raygate {

namespace {

// Seconds below two minutes ("45 s"), else minutes to a tenth ("6.3 min"), so an estimate and
// its budget compare at a glance.
// Milliseconds and tenths where whole seconds would round a fast tracer's rounds to "0 s".
std::string span_text(double seconds) {
  if (seconds < 0.1) return fmt::format("{:.0f} ms", 1000.0 * seconds);
  if (seconds < 10.0) return fmt::format("{:.1f} s", seconds);
  if (seconds < 120.0) return fmt::format("{:.0f} s", seconds);
  return fmt::format("{:.1f} min", seconds / 60.0);
}

// A margin on what the advice asks for: the estimate is of a typical scene, and half the
// scenes take longer than it.
constexpr double kAdviceMargin = 1.25;

// How far the scenes measured so far may put the estimate last said off before it is said again
// (issue 39 holds an estimate to +-30% of the time taken).
constexpr double kRestateFraction = 0.3;

// What would decide a suite the budget cannot: each lever with its number.
std::string advice(const Estimate& estimate, const EstimateShape& shape) {
  std::string text = fmt::format(
      "what would: --max-minutes {:.0f}; or {} of a CI matrix, each `{} --shard K/{}` "
      "with this budget (docs/shards.md)",
      std::ceil(kAdviceMargin * estimate.total_seconds / 60.0),
      count_text(estimate.shards_needed, "shard"), shape.command, estimate.shards_needed);
  if (estimate.tracer_render_seconds_to_fit > 0.0) {
    text += fmt::format(
        "; or a suite whose renders take about {:.2g} s (raygate calibrate "
        "--target-seconds {:.2g}, docs/calibrate.md)",
        estimate.tracer_render_seconds_to_fit, estimate.tracer_render_seconds_to_fit);
  }
  return text;
}

}  // namespace

double scene_seconds(const RoundCost& cost, const EstimateShape& shape, std::size_t rounds) {
  const double warmups = static_cast<double>(std::max(shape.warmup_runs, 0)) *
                         (cost.normalizer_seconds + cost.tracers_seconds);
  const std::size_t normalizer_rounds =
      shape.normalizer_rounds == 0 ? rounds : std::min(rounds, shape.normalizer_rounds);
  const double runs = warmups + static_cast<double>(normalizer_rounds) * cost.normalizer_seconds +
                      static_cast<double>(rounds) * cost.tracers_seconds;
  return runs * std::max(cost.overhead_factor, 1.0);
}

namespace {

// Whether `e.total_seconds` fits the budget and, where not, what would: the fewest shards, and
// the render time of one tracer run (`render_seconds` now) that would.
void judge_budget(Estimate& e, const EstimateShape& shape, double render_seconds) {
  e.fits_scene_limit =
      shape.scene_max_seconds <= 0.0 || e.seconds_per_scene <= shape.scene_max_seconds;
  if (shape.budget_seconds <= 0.0 || e.total_seconds <= shape.budget_seconds) return;
  e.fits_budget = false;
  // Clamped before it becomes a count: a budget of 1e-300 minutes asks for 5e300 shards, which
  // no integer holds (UBSan found the cast).
  const double most = static_cast<double>(std::max<std::size_t>(shape.scenes, 2));
  e.shards_needed = static_cast<std::size_t>(
      std::clamp(std::ceil(kAdviceMargin * e.total_seconds / shape.budget_seconds), 2.0, most));
  // Smaller renders shrink every program's run alike (the baseline renders the same smaller
  // pictures), so the tracer's render time scales by the budget's share of the estimate.
  if (render_seconds > 0.0) {
    e.tracer_render_seconds_to_fit =
        render_seconds * shape.budget_seconds / (kAdviceMargin * e.total_seconds);
    // Below what calibrate can size a suite for, a smaller suite is no advice: the budget is
    // the problem (--max-minutes 1e-300 advised --target-seconds 5e-301).
    if (e.tracer_render_seconds_to_fit < kMinTargetSeconds) e.tracer_render_seconds_to_fit = 0.0;
  }
}

double render_seconds(const RoundCost& cost, std::size_t tracer_count) {
  return tracer_count > 0 ? cost.tracers_seconds / static_cast<double>(tracer_count) : 0.0;
}

}  // namespace

Estimate estimate_measurement(const RoundCost& cost, const EstimateShape& shape, std::size_t rounds,
                              std::size_t tracer_count) {
  Estimate e;
  e.rounds_per_scene = rounds;
  e.seconds_per_scene = scene_seconds(cost, shape, rounds);
  e.total_seconds = e.seconds_per_scene * static_cast<double>(shape.scenes);
  judge_budget(e, shape, render_seconds(cost, tracer_count));
  return e;
}

Estimate estimate_from_scenes(const std::vector<double>& scene_seconds, const EstimateShape& shape,
                              double render_seconds) {
  Estimate e;
  if (scene_seconds.empty()) return e;
  double sum = 0.0;
  for (const double seconds : scene_seconds) sum += seconds;
  e.seconds_per_scene = sum / static_cast<double>(scene_seconds.size());
  e.total_seconds = e.seconds_per_scene * static_cast<double>(shape.scenes);
  judge_budget(e, shape, render_seconds);
  return e;
}

std::vector<std::string> estimate_lines(const Estimate& estimate, const EstimateShape& shape,
                                        const std::string& basis) {
  std::vector<std::string> lines;
  std::string line =
      fmt::format("estimate {}: {} x {} = {}", basis, count_text(shape.scenes, "scene"),
                  span_text(estimate.seconds_per_scene), span_text(estimate.total_seconds));
  if (shape.budget_seconds > 0.0) {
    line += fmt::format(" for a budget of {} (--max-minutes {:g})", span_text(shape.budget_seconds),
                        shape.budget_seconds / 60.0);
  }
  lines.push_back(std::move(line));
  if (!estimate.fits_budget) {
    lines.push_back("  the budget cannot decide every scene at this pace; " +
                    advice(estimate, shape));
  }
  if (!estimate.fits_scene_limit) {
    lines.push_back(
        fmt::format("  a scene needs about {}, beyond --max-seconds {:g}: it stops "
                    "INCONCLUSIVE unless given more",
                    span_text(estimate.seconds_per_scene), shape.scene_max_seconds));
  }
  return lines;
}

EstimateShape estimate_shape(const MeasureContext& context, std::size_t scenes,
                             const std::string& command) {
  EstimateShape shape;
  shape.scenes = scenes;
  shape.warmup_runs = context.schedule.warmup_runs;
  shape.normalizer_rounds = context.schedule.normalizer_rounds;
  shape.budget_seconds = 60.0 * context.stopping.max_minutes;
  shape.scene_max_seconds = context.stopping.max_seconds;
  shape.command = "raygate " + command;
  return shape;
}

std::size_t fewest_compare_rounds(const MeasureContext& context, double decision_alpha) {
  if (exact_timing(context)) return 2;
  std::size_t fewest = min_values_for_median_sequence(decision_alpha);
  for (const SuiteScene& scene : context.scenes) {
    fewest = std::min(
        fewest, min_values_for_median_sequence(context.policy.for_scene(scene.id).significance));
  }
  return std::max(fewest, rounds_to_decide(context.stopping));
}

RoundCost round_cost(const Round& round, double seconds_spent, int warmup_runs) {
  RoundCost cost;
  for (const auto& [role, run] : round.runs) {
    if (role == role_name(Role::baseline)) {
      cost.normalizer_seconds += run.wall_seconds;
    } else {
      cost.tracers_seconds += run.wall_seconds;
    }
  }
  // The warm-ups ran every contender once each, about as long as this round's runs.
  const double runs =
      (1.0 + std::max(warmup_runs, 0)) * (cost.normalizer_seconds + cost.tracers_seconds);
  if (runs > 0.0 && seconds_spent > runs) cost.overhead_factor = seconds_spent / runs;
  return cost;
}

MeasurementEstimate::MeasurementEstimate(EstimateShape shape, std::size_t fewest_rounds,
                                         std::size_t tracer_count, ProgressSink& progress)
    : shape_(std::move(shape)),
      fewest_rounds_(fewest_rounds),
      tracer_count_(tracer_count),
      progress_(progress) {}

StopRule MeasurementEstimate::watch(StopRule rule, const std::string& scene_id) {
  const std::size_t index = scenes_watched_++;
  if (index == 0) first_scene_ = scene_id;
  return [this, index, rule = std::move(rule)](const std::vector<Round>& rounds,
                                               double seconds_spent) {
    if (index == 0 && rounds.size() == 1) first_round(rounds, seconds_spent);
    const StopDecision decision = rule(rounds, seconds_spent);
    if (decision != StopDecision::continue_measuring) {
      if (index == 0) first_scene_done(rounds, seconds_spent, decision);
      scene_done(seconds_spent, decision);
    }
    return decision;
  };
}

void MeasurementEstimate::scene_done(double seconds_spent, StopDecision decision) {
  scene_seconds_.push_back(seconds_spent);
  if (decision != StopDecision::stop_converged) ++undecided_;
  const std::size_t done = scene_seconds_.size();
  if (done < 2 || done >= shape_.scenes || said_total_seconds_ <= 0.0) return;
  const Estimate estimate = estimate_from_scenes(
      scene_seconds_, shape_, cost_ ? render_seconds(*cost_, tracer_count_) : 0.0);
  // Said again only when the scenes so far put the last estimate off by more than the margin an
  // estimate is held to: one scene's rounds often do not predict the others'.
  if (std::abs(estimate.total_seconds - said_total_seconds_) <=
      kRestateFraction * said_total_seconds_) {
    return;
  }
  const std::string basis = fmt::format(
      "again, from the first {} of {} (it said {}{})", done, count_text(shape_.scenes, "scene"),
      span_text(said_total_seconds_),
      undecided_ > 0 ? fmt::format("; {} not decided in its share, so at least", undecided_)
                     : std::string());
  for (const std::string& line : estimate_lines(estimate, shape_, basis)) progress_.line(line);
  said_total_seconds_ = estimate.total_seconds;
}

void MeasurementEstimate::first_round(const std::vector<Round>& rounds, double seconds_spent) {
  cost_ = round_cost(rounds.front(), seconds_spent, shape_.warmup_runs);
  const Estimate estimate = estimate_measurement(*cost_, shape_, fewest_rounds_, tracer_count_);
  const std::string basis = fmt::format(
      "from {}'s first round (baseline {}, {} {} a round, +{:.0f}% between the runs) "
      "at the fewest rounds a verdict needs ({}), so at least",
      first_scene_, span_text(cost_->normalizer_seconds), tracer_count_ > 1 ? "tracers" : "tracer",
      span_text(cost_->tracers_seconds), 100.0 * (cost_->overhead_factor - 1.0), fewest_rounds_);
  for (const std::string& line : estimate_lines(estimate, shape_, basis)) progress_.line(line);
}

void MeasurementEstimate::first_scene_done(const std::vector<Round>& rounds, double seconds_spent,
                                           StopDecision decision) {
  if (!cost_ || shape_.scenes < 2) return;
  if (decision != StopDecision::stop_converged) {
    const double like_it = seconds_spent * static_cast<double>(shape_.scenes);
    if (decision == StopDecision::stop_budget_rounds) {
      // Scenes like it stop at the same limit: what they take is its time, not more.
      progress_.line(fmt::format(
          "estimate: {} stopped undecided at its round limit ({}, {}); scenes like it stop there "
          "too: {} scenes x {} = {}",
          first_scene_, count_text(rounds.size(), "round"), span_text(seconds_spent), shape_.scenes,
          span_text(seconds_spent), span_text(like_it)));
      said_total_seconds_ = like_it;
      return;
    }
    // Its share of the budget ran out: scenes like it need more than theirs, and the first
    // line's floor stands where it was higher ("need more" beside a smaller number read wrong).
    const double floor =
        estimate_measurement(*cost_, shape_, fewest_rounds_, tracer_count_).total_seconds;
    said_total_seconds_ = std::max(floor, like_it);
    progress_.line(fmt::format(
        "estimate: {} was not decided in its share of the budget ({}, {}); scenes like it need "
        "more: over {}",
        first_scene_, count_text(rounds.size(), "round"), span_text(seconds_spent),
        span_text(said_total_seconds_)));
    return;
  }
  // The rounds it took, at the cost of a round as measured over all of them.
  RoundCost cost = *cost_;
  const double per_round = seconds_spent / scene_seconds(cost, shape_, rounds.size());
  cost.overhead_factor *= per_round;
  const Estimate estimate = estimate_measurement(cost, shape_, rounds.size(), tracer_count_);
  const std::string basis = fmt::format("from {} (decided in {} rounds, {}), for scenes like it",
                                        first_scene_, rounds.size(), span_text(seconds_spent));
  for (const std::string& line : estimate_lines(estimate, shape_, basis)) progress_.line(line);
  said_total_seconds_ = estimate.total_seconds;
}

}  // namespace raygate

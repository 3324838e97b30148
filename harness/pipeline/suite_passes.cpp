#include "pipeline/suite_passes.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "core/format.h"
#include "core/interrupt.h"
#include "core/path_component.h"
#include "results/scores.h"

namespace raygate::suite_pass {

void summarize_ratios(SceneResult& scene, const SuiteMeasurement& m) {
  if (scene.runs.rounds.empty()) return;
  for (const Role role : m.tracer_roles) {
    scene.ratios[role] = summarize_ratio(round_samples(scene.runs.rounds, role));
  }
}

void update_scores(ResultsDocument& document, const SuiteMeasurement& m) {
  document.scores = suite_scores(document.scenes, m.tracer_roles);
}

KeptDocument keep(const ResultsDocument& document, const SuiteMeasurement& m) {
  return keep_document(document, m.out, m.work_dir / "results.json");
}

std::filesystem::path scene_dir(const SuiteMeasurement& m, const SuiteScene& entry) {
  return join_component(m.work_dir / "scenes", entry.id, "scene id");
}

namespace {

// More rounds of a measured scene under `stop` and `schedule`, shown as `label` (its place in
// the pass), its ratios summarized again. Returns false when a run failed: the scene's change is
// then dropped, as in the first pass, since the failure is its result.
bool continue_measuring(SceneResult& scene, const StopRule& stop, const ScheduleOptions& schedule,
                        ProgressState state, const SuiteMeasurement& m, Executor& executor,
                        PipelineIo& io) {
  state.round = scene.runs.rounds.size();
  io.progress.update(state);
  const RoundObserver observe = [&](const std::vector<Round>& rounds, double) {
    state.round = rounds.size();
    io.progress.update(state);
  };
  scene.runs =
      continue_scene(prepare_scene_input(scene.entry, m), m.contenders, schedule, stop, executor,
                     io.clock, scene_dir(m, scene.entry), std::move(scene.runs), observe);
  summarize_ratios(scene, m);
  if (!scene.runs.failed()) return true;
  scene.status = SceneStatus::failed;
  scene.change.reset();
  scene.change_verdict = ChangeVerdict::inconclusive;
  return false;
}

// What the second pass knows of each scene besides its rounds: whether no more time can go to
// it, and how many visits ended undecided although its estimate said they would not.
struct RevisitState {
  bool spent = false;
  int misses = 0;
};

// About how many seconds more the scene needs: its estimate, doubled for every visit it outlived.
// The estimate projects from the rounds' spread (measure/change.h), which a scene with heavier
// tails than its spread shows outlives visit after visit, one round at a time; backed off, it
// gets longer visits and lets the other scenes go first (the identity tracer's nurbtst, estimated
// a round short 15 times running, took 30 rounds in 2-round visits while balls waited).
double backed_off_seconds(const MeasurementPlan& plan, const SceneResult& scene,
                          const RevisitState& state) {
  return std::ldexp(plan.plan_visit(scene).seconds, std::min(state.misses, 20));
}

// The scenes of `document` stopped undecided for lack of time, the cheapest to decide first (a
// stable order: equal estimates keep the suite's order), leaving out those with no time left.
std::vector<std::size_t> scenes_to_revisit(const ResultsDocument& document,
                                           const MeasurementPlan& plan,
                                           const std::vector<RevisitState>& states) {
  std::vector<std::pair<double, std::size_t>> undecided;
  for (std::size_t i = 0; i < document.scenes.size(); ++i) {
    const SceneResult& scene = document.scenes[i];
    if (states[i].spent || scene.runs.failed() || scene.runs.rounds.empty() ||
        scene.runs.stop_reason != to_string(StopDecision::stop_budget_time)) {
      continue;
    }
    undecided.emplace_back(backed_off_seconds(plan, scene, states[i]), i);
  }
  std::stable_sort(undecided.begin(), undecided.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::size_t> order;
  for (const auto& [seconds, index] : undecided) order.push_back(index);
  return order;
}

// One visit of the second pass to `scene`; false when no time was left for it.
bool revisit(SceneResult& scene, RevisitState& state, std::size_t visit, std::size_t undecided,
             const SuiteMeasurement& m, MeasurementPlan& plan, Executor& executor, PipelineIo& io) {
  const double seconds_needed = backed_off_seconds(plan, scene, state);
  const std::optional<StopRule> stop = plan.revisit_stop(scene, undecided, seconds_needed);
  if (!stop) return false;
  const std::size_t rounds_before = scene.runs.rounds.size();
  ScheduleOptions schedule = m.schedule;
  if (const std::size_t repeats = plan.plan_visit(scene).repeats; repeats > 0) {
    schedule.repeats = repeats;
  }
  const ProgressState progress{
      visit, visit + undecided - 1, scene.entry.id + " (again)", 0, 0.0, 0.0, -1.0};
  if (continue_measuring(scene, *stop, schedule, progress, m, executor, io)) plan.rejudge(scene);
  // A visit that ran no round had no time; a scene still without an estimate (a change on the
  // limit) had its even share, and more of the same would not decide it.
  if (scene.runs.stop_reason == to_string(StopDecision::stop_budget_time)) ++state.misses;
  return scene.runs.rounds.size() > rounds_before && std::isfinite(plan.plan_visit(scene).seconds);
}

}  // namespace

// Estimated anew after every visit, a scene that needed more than its estimate competes again
// instead of keeping the time, and the scenes after it still get their turn. The document is
// kept after each visit as after the first pass.
void revisit_scenes(ResultsDocument& document, const SuiteMeasurement& m, MeasurementPlan& plan,
                    Executor& executor, PipelineIo& io) {
  std::vector<RevisitState> states(document.scenes.size());
  for (std::size_t visit = 1;; ++visit) {
    throw_if_interrupted("between scenes");
    const std::vector<std::size_t> order = scenes_to_revisit(document, plan, states);
    if (order.empty()) return;
    SceneResult& scene = document.scenes[order.front()];
    RevisitState& state = states[order.front()];
    const std::size_t runs_before = scene.runs.rounds.size();
    if (!revisit(scene, state, visit, order.size(), m, plan, executor, io)) state.spent = true;
    if (scene.runs.rounds.size() == runs_before && !scene.runs.failed()) continue;
    update_scores(document, m);
    keep(document, m);
    io.progress.line(fmt::format("[second pass {}, {} undecided] {}", visit,
                                 count_text(order.size(), "scene"),
                                 scene_line(scene, m.tracer_roles)));
  }
}

void add_ratio_rounds(ResultsDocument& document, const SuiteMeasurement& m, MeasurementPlan& plan,
                      Executor& executor, PipelineIo& io) {
  std::vector<std::size_t> wanting;
  for (std::size_t i = 0; i < document.scenes.size(); ++i) {
    const SceneResult& scene = document.scenes[i];
    if (!scene.runs.failed() && !scene.runs.rounds.empty() && plan.wants_ratio_rounds(scene)) {
      wanting.push_back(i);
    }
  }
  for (std::size_t k = 0; k < wanting.size(); ++k) {
    throw_if_interrupted("between scenes");
    SceneResult& scene = document.scenes[wanting[k]];
    const std::optional<StopRule> stop = plan.ratio_rounds_stop(scene, wanting.size() - k);
    if (!stop) continue;
    const std::size_t rounds_before = scene.runs.rounds.size();
    const std::string change_stop_reason = scene.runs.stop_reason;
    ScheduleOptions schedule = m.schedule;
    schedule.normalizer_rounds = 0;  // the baseline joins every ratio round
    const ProgressState progress{k + 1, wanting.size(), scene.entry.id + " (ratio)", 0, 0.0, 0.0,
                                 -1.0};
    if (continue_measuring(scene, *stop, schedule, progress, m, executor, io)) {
      const std::string ratio_stop_reason = scene.runs.stop_reason;
      scene.runs.stop_reason = change_stop_reason;  // the scene's stop reason stays its change's
      plan.rejudge_after_ratio_rounds(scene, rounds_before, ratio_stop_reason);
    }
    update_scores(document, m);
    keep(document, m);
    io.progress.line(
        fmt::format("[ratio {}/{}] {}", k + 1, wanting.size(), scene_line(scene, m.tracer_roles)));
  }
}

}  // namespace raygate::suite_pass

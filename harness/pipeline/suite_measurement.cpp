#include "pipeline/suite_measurement.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "core/format.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/path_component.h"
#include "measure/stop_words.h"
#include "core/sha256.h"
#include "core/time_text.h"
#include "gate/growth_gate.h"
#include "measure/machine_context.h"
#include "compare/noisy_image_check.h"
#include "pipeline/document_output.h"
#include "pipeline/run_images.h"
#include "pipeline/suite_passes.h"
#include "report/ratio_interval_text.h"
#include "runner/baseline_cost_cache.h"
#include "runner/cachegrind.h"
#include "runner/deadline_executor.h"
#include "runner/idle_poll.h"
#include "runner/scene_files.h"
#include "results/scores.h"
#include "scaling/scaling_stage.h"
#include "scaling/scaling_text.h"

namespace raygate {

using suite_pass::add_ratio_rounds;
using suite_pass::keep;
using suite_pass::revisit_scenes;
using suite_pass::scene_dir;
using suite_pass::summarize_ratios;
using suite_pass::update_scores;

namespace {

void check_images(SceneResult& result, const SuiteMeasurement& m, const GoldenManifest& manifest,
                  const ResultsDocument& document) {
  const SuiteScene& e = result.entry;
  const GoldenEntry rendered{
      e.id, e.scene, e.size, e.width,       e.height, document.baseline.sampling,
      {},   {},      {},     document.suite};
  for (const Role role : m.tracer_roles) {
    const RunRecord* run = result.runs.first_run(role);
    if (run == nullptr) continue;  // failed before producing an image; the failure says why
    if (m.images == ImageKind::monte_carlo) {
      result.images.push_back(check_runs_against_golden(
          role, run_images(result.runs, role), m.golden_dir, manifest, rendered,
          noisy_thresholds_for(m.scenes.size(), m.policy.for_scene(e.id).image_tolerance),
          m.work_dir / "evidence"));
      continue;
    }
    result.images.push_back(check_against_golden(role, run->image, m.golden_dir, manifest, rendered,
                                                 m.policy.for_scene(result.entry.id).image,
                                                 m.work_dir / "evidence"));
  }
}

// Remaining time: the mean time per finished scene for every scene not finished yet.
double eta_seconds(double elapsed_done, std::size_t done, std::size_t total, double current) {
  if (done == 0) return -1.0;
  const double per_scene = elapsed_done / static_cast<double>(done);
  return per_scene * static_cast<double>(total - done) - std::min(current, per_scene);
}

}  // namespace

std::filesystem::path fresh_run_dir(const std::filesystem::path& parent, const std::string& stem) {
  std::filesystem::create_directories(parent);
  for (int n = 1;; ++n) {
    const std::filesystem::path dir =
        join_component(parent, n == 1 ? stem : fmt::format("{}-{}", stem, n), "run folder name");
    if (std::filesystem::create_directory(dir)) return dir;  // false: it exists (another run's)
  }
}

SuiteMeasurement suite_measurement(const MeasureContext& context, const std::string& run_name,
                                   const std::filesystem::path& out) {
  SuiteMeasurement m;
  m.work_dir = fresh_run_dir(context.cache_dir / "runs", run_name);
  m.out = out.empty() ? m.work_dir / "results.json" : std::filesystem::absolute(out);
  m.scene_cache = join_component(context.cache_dir / "scenes", context.suite.name, "suite name");
  m.golden_dir = context.golden_dir;
  m.policy = context.policy;
  m.scenes = context.scenes;
  m.schedule = context.schedule;
  m.formats = {context.adapter.scene_format};
  m.images = context.adapter.images;
  m.budget_seconds = 60.0 * context.stopping.max_minutes;
  if (!exact_timing(context)) m.idle_poll_device = context.idle_poll_device;
  return m;
}

ResultsDocument new_document(DocumentKind kind, const MeasureContext& context,
                             const BaselineTool& baseline) {
  ResultsDocument document;
  document.kind = kind;
  document.raygate_version = RAYGATE_VERSION " (git " RAYGATE_GIT_COMMIT ")";  // as --version
  document.started_at = utc_timestamp();
  document.machine = probe_machine_context();
  document.baseline.version = baseline.version_line();
  document.baseline.source_sha256 = baseline.source_hash();
  document.baseline.sampling = context.suite.sampling;
  document.baseline.timing = std::string(timing_mode(context).baseline_clock());
  document.suite = context.suite.name;
  document.settings = measure_settings(context);
  // Whose goldens judge this run's images ("none": the tracer has none yet), so a report can
  // say so once instead of once per scene.
  document.settings.goldens = golden_owner(load_golden_manifest(context.golden_dir));
  if (context.shard) document.shard = to_string(context.shard->spec);
  return document;
}

namespace {

// The one line an interrupted measurement ends with: what was kept, and where.
std::string kept_message(const Interrupted& stop, const ResultsDocument& document,
                         const SuiteMeasurement& m, const KeptDocument& kept) {
  if (!kept.failed.empty()) {
    return fmt::format("interrupted by {}: {} of {} measured (complete: false); {}",
                       signal_name(stop.signal()), document.scenes.size(),
                       count_text(m.scenes.size(), "scene"), describe_kept(kept));
  }
  return fmt::format("interrupted by {}: kept {} of {} in {} (complete: false)",
                     signal_name(stop.signal()), document.scenes.size(),
                     count_text(m.scenes.size(), "scene"), kept.path->string());
}

void measure_scenes(ResultsDocument& document, const SuiteMeasurement& m, MeasurementPlan& plan,
                    PipelineIo& io) {
  Clock& clock = io.clock;
  ProgressSink& progress = io.progress;
  const GoldenManifest manifest = load_golden_manifest(m.golden_dir);
  const double started = clock.now_seconds();
  double elapsed_done = 0.0;
  DeadlineExecutor bounded(io.executor, clock, measurement_deadline(started, m.budget_seconds));
  Executor& executor = m.budget_seconds > 0.0 ? static_cast<Executor&>(bounded) : io.executor;
  for (std::size_t index = 0; index < m.scenes.size(); ++index) {
    throw_if_interrupted("between scenes");
    const SuiteScene& entry = m.scenes[index];
    ProgressState state{index + 1,
                        m.scenes.size(),
                        entry.id,
                        0,
                        0.0,
                        0.0,
                        eta_seconds(elapsed_done, index, m.scenes.size(), 0.0)};
    progress.update(state);

    SceneResult result;
    result.entry = entry;
    const SceneInput input = prepare_scene_input(entry, m);
    result.scene_sha256 = sha256_file_hex(input.nff);
    const RoundObserver observe = [&](const std::vector<Round>& rounds, double spent) {
      state.round = rounds.size();
      if (rounds.size() >= 2 && !m.tracer_roles.empty()) {
        const RatioSummary summary = summarize_ratio(round_samples(rounds, m.tracer_roles.back()));
        state.ratio = summary.ratio;
        state.relative_half_width = summary.relative_half_width;
      }
      state.eta_seconds = eta_seconds(elapsed_done, index, m.scenes.size(), spent);
      progress.update(state);
    };
    ScheduleOptions schedule = m.schedule;
    schedule.repeats_from_rounds = plan.repeats(entry);
    result.runs = measure_scene(input, m.contenders, schedule, plan.first_visit_stop(entry),
                                executor, clock, scene_dir(m, entry), observe);
    result.status = result.runs.failed() ? SceneStatus::failed : SceneStatus::measured;
    summarize_ratios(result, m);
    check_images(result, m, manifest, document);
    if (!result.runs.failed()) plan.finish_scene(result);

    document.scenes.push_back(std::move(result));
    update_scores(document, m);
    keep(document, m);
    elapsed_done = clock.now_seconds() - started;
    progress.line(fmt::format("[{}/{}] {}", index + 1, m.scenes.size(),
                              scene_line(document.scenes.back(), m.tracer_roles)));
  }
  // Only a whole-measurement budget leaves a scene undecided for want of its share.
  if (plan.revisits() && m.budget_seconds > 0.0) {
    revisit_scenes(document, m, plan, executor, io);
  }
  add_ratio_rounds(document, m, plan, executor, io);
}

}  // namespace

SceneInput prepare_scene_input(const SuiteScene& entry, const SuiteMeasurement& m) {
  SceneInput input;
  input.entry = entry;
  input.nff = prepare_scene(entry, m.scene_cache);
  input.files[SceneFormat::nff] = input.nff;
  for (const SceneFormat format : m.formats) {
    if (format != SceneFormat::nff) {
      input.files[format] = prepare_converted_scene(input.nff, format, m.scene_cache);
    }
  }
  for (const auto& [format, file] : input.files) {
    if (const std::optional<FileStamp> stamp = file_stamp(file))
      input.prepared_stamps[file] = *stamp;
  }
  return input;
}

namespace {

// Idle CPUs held polling for the whole measurement, and the document saying whether they were.
// A machine that refuses (not root, a container) still measures validly, only noisier for a
// tracer that sleeps during its run, so the refusal is said once and recorded, not an error.
std::optional<IdlePollHold> hold_idle_polling(MeasurementSettings& settings,
                                              const SuiteMeasurement& m, PipelineIo& io) {
  if (m.idle_poll_device.empty()) return std::nullopt;
  IdlePollHold hold(m.idle_poll_device);
  if (hold.held()) {
    settings.cpu_idle = CpuIdle::poll;
    return hold;
  }
  settings.cpu_idle = CpuIdle::os;
  settings.cpu_idle_refused = hold.why_not();
  io.progress.status("note: idle CPUs not held polling (" + hold.why_not() +
                     "): a tracer that sleeps during its runs measures noisier "
                     "(docs/statistics.md §6d); --no-idle-poll stops asking");
  return std::nullopt;
}

}  // namespace

void measure_suite(ResultsDocument& document, const SuiteMeasurement& m, MeasurementPlan& plan,
                   PipelineIo& io) {
  const std::optional<IdlePollHold> idle_polling = hold_idle_polling(document.settings, m, io);
  // Within it a signal is not fatal at once: the running child's group is killed, the scenes
  // finished so far are written, and Interrupted says where.
  const InterruptScope stop_here;
  try {
    measure_scenes(document, m, plan, io);
  } catch (const Interrupted& stop) {
    document.complete = false;
    throw Interrupted(stop.signal(), kept_message(stop, document, m, keep(document, m)));
  }
  document.complete = true;
}

MeasuredDocument measure_document(ResultsDocument document, const SuiteMeasurement& m,
                                  MeasurementPlan& plan, const std::string& opening,
                                  PipelineIo& io) {
  io.progress.line(opening);
  measure_suite(document, m, plan, io);
  for (const std::string& line : plan.finish_suite(document)) io.progress.line(line);
  document.finished_at = utc_timestamp();
  const ScalingAnalysis scaling = attach_scaling(document, scaling_limits(m.policy));
  for (const std::string& line : scaling_lines(scaling)) io.progress.line(line);
  KeptDocument kept = keep(document, m);
  const std::filesystem::path where = kept.path.value_or(m.out);
  return {std::move(document), where, std::move(kept.failed)};
}

BaselineContender baseline_contender(const MeasureContext& context,
                                     const std::string& baseline_source_sha256) {
  // Its own limit a run; the user's budget bounds it too (issue 25, class 10).
  const double timeout_seconds = budgeted_run_seconds(
      context.stopping, std::chrono::duration<double>(kBaselineRunLimit).count());
  const std::chrono::milliseconds timeout(static_cast<long long>(1000.0 * timeout_seconds));
  BaselineContender baseline(context.tools.baseline, context.suite.sampling, timeout, "none",
                             &timing_mode(context));
  if (under_cachegrind(context)) {
    baseline.simulate(
        {*context.cachegrind,
         std::make_shared<BaselineCostCache>(context.cache_dir / "simulated-baseline"),
         baseline_source_sha256});
  }
  return baseline;
}

std::string scene_line(const SceneResult& scene, const std::vector<Role>& tracer_roles) {
  std::string text = fmt::format("{:<10}", scene.entry.id);
  for (const Role role : tracer_roles) {
    if (const RatioSummary* r = scene.ratio(role)) {
      text += fmt::format("  {}{}", tracer_roles.size() > 1 ? role_name(role) + " " : "",
                          ratio_interval_text(*r));
    }
  }
  text += fmt::format("  {}, {}", count_text(scene.runs.rounds.size(), "round"),
                      stop_reason_text(scene.runs.stop_reason));
  if (const std::string repeats = repeats_note(scene.runs.rounds); !repeats.empty()) {
    text += ", " + repeats;
  }
  if (const std::string note = determinism_note(scene.runs); !note.empty()) text += "  " + note;
  if (scene.runs.failed()) {
    const RunRecord& run = *scene.runs.failed_run;
    text += fmt::format("  FAILED {}: {} (log: {})", to_string(scene.runs.failed_role), run.failure,
                        run.log.string());
  }
  for (const ImageCheck& check : scene.images) {
    // No golden: one note at the end, not per scene.
    if (check.verdict == ImageVerdict::missing) continue;
    const std::string what = check_label(check, "-vs-");
    if (check.noisy) {  // its line starts with its own verdict ("fail (biased): ...")
      text += fmt::format("  image {} {}", what, check_detail(check));
      continue;
    }
    const std::string detail =
        check.metrics && check.metrics->identical() ? "identical" : check_detail(check);
    text += fmt::format("  image {} {} ({})", what, to_string(check.verdict), detail);
  }
  return text;
}

}  // namespace raygate

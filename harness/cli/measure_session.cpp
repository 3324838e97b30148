#include "cli/measure_session.h"

#include <fmt/core.h>

#include <algorithm>

#include "core/error.h"
#include "core/exit_codes.h"
#include "core/sha256.h"
#include "runner/scene_files.h"

namespace raygate::cli {

namespace {

SceneInput prepare_input(const SuiteScene& entry, const SuiteMeasurement& m) {
  SceneInput input;
  input.entry = entry;
  input.nff = prepare_scene(entry, m.scene_cache);
  input.files[SceneFormat::nff] = input.nff;
  for (const SceneFormat format : m.formats) {
    if (format != SceneFormat::nff) {
      throw UsageError(fmt::format("scene format '{}' cannot be prepared yet", to_string(format)));
    }
  }
  return input;
}

void summarize_ratios(SceneResult& result, const SuiteMeasurement& m) {
  if (result.runs.rounds.empty()) return;
  for (const std::string& role : m.tracer_roles) {
    result.ratios[role] = summarize_ratio(round_samples(result.runs.rounds, role));
  }
}

void check_images(SceneResult& result, const SuiteMeasurement& m, const GoldenManifest& manifest) {
  for (const std::string& role : m.tracer_roles) {
    const RunRecord* run = result.runs.first_run(role);
    if (run == nullptr) continue;  // failed before producing an image; the failure says why
    result.images.push_back(check_against_golden(role, run->image, m.golden_dir, manifest,
                                                 result.entry.id, m.thresholds,
                                                 m.work_dir / "evidence"));
  }
}

void update_scores(ResultsDocument& document, const std::vector<std::string>& roles) {
  document.scores.clear();
  for (const std::string& role : roles) {
    std::vector<std::vector<RoundSample>> per_scene;
    for (const SceneResult& scene : document.scenes) {
      if (scene.status == "measured") per_scene.push_back(round_samples(scene.runs.rounds, role));
    }
    if (!per_scene.empty()) document.scores[role] = suite_score(per_scene);
  }
}

// Remaining time: the mean time per finished scene for every scene not finished yet.
double eta_seconds(double elapsed_done, std::size_t done, std::size_t total, double current) {
  if (done == 0) return -1.0;
  const double per_scene = elapsed_done / static_cast<double>(done);
  return per_scene * static_cast<double>(total - done) - std::min(current, per_scene);
}

}  // namespace

void measure_suite(ResultsDocument& document, const SuiteMeasurement& m, Executor& executor,
                   Clock& clock, Progress& progress) {
  const GoldenManifest manifest = load_golden_manifest(m.golden_dir);
  const double started = clock.now_seconds();
  double elapsed_done = 0.0;
  for (std::size_t index = 0; index < m.scenes.size(); ++index) {
    const SuiteScene& entry = m.scenes[index];
    ProgressState state{index + 1, m.scenes.size(), entry.id, 0, 0.0, 0.0,
                        eta_seconds(elapsed_done, index, m.scenes.size(), 0.0)};
    progress.update(state);

    SceneResult result;
    result.entry = entry;
    const SceneInput input = prepare_input(entry, m);
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
    result.runs = measure_scene(input, m.contenders, m.schedule, m.stop, executor, clock,
                                m.work_dir / "scenes" / entry.id, observe);
    result.status = result.runs.failed() ? "failed" : "measured";
    summarize_ratios(result, m);
    check_images(result, m, manifest);
    if (m.finish_scene && !result.runs.failed()) m.finish_scene(result);

    document.scenes.push_back(std::move(result));
    update_scores(document, m.tracer_roles);
    write_results(document, m.out);
    elapsed_done = clock.now_seconds() - started;
    progress.line(fmt::format("[{}/{}] {}", index + 1, m.scenes.size(),
                              scene_line(document.scenes.back(), m.tracer_roles)));
  }
  document.complete = true;
}

std::string scene_line(const SceneResult& scene, const std::vector<std::string>& tracer_roles) {
  std::string text = fmt::format("{:<10}", scene.entry.id);
  for (const std::string& role : tracer_roles) {
    if (const RatioSummary* r = scene.ratio(role)) {
      text += fmt::format("  {}{:.3f} [{:.3f}, {:.3f}]", tracer_roles.size() > 1 ? role + " " : "",
                          r->ratio, r->ratio_interval.lower, r->ratio_interval.upper);
    }
  }
  text += fmt::format("  {} rounds, {}", scene.runs.rounds.size(), scene.runs.stop_reason);
  if (scene.runs.failed()) {
    const RunRecord& run = *scene.runs.failed_run;
    text += fmt::format("  FAILED {}: {} (log: {})", scene.runs.failed_role, run.failure,
                        run.log.string());
  }
  for (const ImageCheck& check : scene.images) {
    text += fmt::format("  image {}{}", check.verdict,
                        check.metrics ? " (" + (check.metrics->identical() ? std::string("identical")
                                                                          : summarize(*check.metrics)) + ")"
                                      : " (" + check.error + ")");
  }
  return text;
}

int run_exit_code(const ResultsDocument& document) {
  bool unmeasured = !document.complete;
  bool image_failed = false;
  for (const SceneResult& scene : document.scenes) {
    unmeasured = unmeasured || scene.status != "measured";
    for (const ImageCheck& check : scene.images) {
      unmeasured = unmeasured || check.verdict == "error";
      image_failed = image_failed || check.failed();
    }
  }
  if (unmeasured) return to_int(ExitCode::infrastructure);
  if (image_failed) return to_int(ExitCode::regression);
  return to_int(ExitCode::pass);
}

}  // namespace raygate::cli

#include "pipeline/explain_stage.h"

#include <fmt/core.h>

#include <chrono>

#include "core/error.h"
#include "core/path_component.h"
#include "explain/explain_runs.h"
#include "measure/change.h"

namespace raygate {
namespace {

bool regressed(const SceneResult& scene) {
  return scene.change && !scene.runs.failed() && scene.change_verdict == ChangeVerdict::regressed;
}

std::optional<Explanation> explain_one(const SceneResult& scene, const MeasureContext& context,
                                       const Cachegrind& cachegrind, const SuiteMeasurement& m,
                                       const Contender& base, const Contender& head,
                                       Executor& executor) {
  if (under_cachegrind(context)) return explain_simulated_runs(scene.runs, cachegrind);
  const SceneInput input = prepare_scene_input(scene.entry, m);
  const std::filesystem::path dir =
      join_component(m.work_dir / "explain", scene.entry.id, "scene id");
  return explain_by_profiling(input, base, head, cachegrind, dir, executor,
                              native_pair_seconds(scene.runs));
}

}  // namespace

std::vector<std::string> explain_regressed_scenes(ResultsDocument& document,
                                                  const MeasureContext& context,
                                                  const SuiteMeasurement& m, const Contender& base,
                                                  const Contender& head, Executor& executor) {
  if (!under_cachegrind(context) && !context.explain) return {};
  std::vector<SceneResult*> targets;
  for (SceneResult& scene : document.scenes) {
    if (regressed(scene)) targets.push_back(&scene);
  }
  if (targets.empty()) return {};
  const Cachegrind cachegrind = context.cachegrind ? *context.cachegrind : find_cachegrind();
  std::vector<std::string> lines;
  const auto started = std::chrono::steady_clock::now();
  std::size_t explained = 0;
  for (SceneResult* scene : targets) {
    try {
      scene->explanation = explain_one(*scene, context, cachegrind, m, base, head, executor);
      if (scene->explanation) ++explained;
    } catch (const InfraError& e) {
      lines.push_back(fmt::format("{}: not explained: {}", scene->entry.id, e.what()));
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  lines.push_back(fmt::format(
      "explained {} regressed {} with {} in {:.1f} s{}", explained,
      explained == 1 ? "scene" : "scenes",
      under_cachegrind(context) ? profiler_name(cachegrind) : callgrind_profiler_name(cachegrind),
      seconds,
      under_cachegrind(context) ? " (from the sim runs' own files)"
                                : " (one profiled run each of base and head)"));
  return lines;
}

}  // namespace raygate

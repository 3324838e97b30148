#include "gate/memory_gate.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/format.h"

namespace raygate {

std::vector<long> own_peaks_kib(const SceneRuns& runs, Role role) {
  std::vector<long> peaks;
  for (const Round& round : runs.rounds) {
    const auto found = round.runs.find(role_name(role));
    if (found == round.runs.end()) continue;
    const RunRecord& run = found->second;
    if (run.ok && run.max_rss_own && run.max_rss_kib > 0) peaks.push_back(run.max_rss_kib);
  }
  return peaks;
}

std::optional<double> median_peak_kib(const SceneRuns& runs, Role role) {
  std::vector<long> peaks = own_peaks_kib(runs, role);
  if (peaks.empty()) return std::nullopt;
  // The same median as the summary's: a summary of the role against itself.
  return summarize_memory(peaks, peaks)->base_kib;
}

std::optional<MemorySummary> scene_memory(const SceneResult& scene) {
  if (!scene.change || scene.runs.failed()) return std::nullopt;
  return summarize_memory(own_peaks_kib(scene.runs, Role::base),
                          own_peaks_kib(scene.runs, Role::head));
}

std::optional<MemoryJudgement> judge_scene_memory(const SceneResult& scene,
                                                  const ScenePolicy& policy) {
  const std::optional<MemorySummary> summary = scene_memory(scene);
  if (!summary) return std::nullopt;
  return MemoryJudgement{*summary, classify_memory(*summary, policy.max_memory_increase),
                         policy.max_memory_increase};
}

std::vector<PeakMethod> peak_methods(const ResultsDocument& document) {
  std::set<PeakMethod> methods;
  for (const SceneResult& scene : document.scenes) {
    for (const Round& round : scene.runs.rounds) {
      for (const Role role : revision_roles(document.kind)) {
        const auto found = round.runs.find(role_name(role));
        if (found != round.runs.end() && found->second.max_rss_own) {
          methods.insert(found->second.peak_method);
        }
      }
    }
  }
  return {methods.begin(), methods.end()};
}

std::string memory_text(double kib) {
  const double mib = kib / 1024.0;
  if (std::abs(mib) < 1.0) return fmt::format("{:.0f} KiB", kib);  // page-level jitter
  if (mib >= 100.0) return fmt::format("{:.0f} MiB", mib);
  return fmt::format("{:.1f} MiB", mib);
}

std::string describe_memory(const MemoryJudgement& j) {
  const MemorySummary& s = j.summary;
  const std::string sign = s.delta_kib < 0.0 ? "-" : "+";
  return fmt::format(
      "head {} vs base {} ({}{}, {}), limit {}, noise {}, {} + {} runs", memory_text(s.head_kib),
      memory_text(s.base_kib), sign, memory_text(std::abs(s.delta_kib)), signed_percent(s.change),
      signed_percent(j.limit, 0), memory_text(s.noise_kib()), s.base_runs, s.head_runs);
}

}  // namespace raygate

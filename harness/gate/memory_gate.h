// Peak memory per scene from a results document's runs (issue 27): each role's own peaks (runs
// started through raygate-meter; older documents hold raygate's peak and are not judged), the
// summary of head against base, its verdict under the policy, and the words a report prints.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gate/policy.h"
#include "measure/memory_change.h"
#include "results/results.h"

namespace raygate {

// The peaks (KiB) of `role`'s runs in the scene's complete rounds that are its own.
std::vector<long> own_peaks_kib(const SceneRuns& runs, Role role);

// The median own peak of `role`; nullopt when it has none.
std::optional<double> median_peak_kib(const SceneRuns& runs, Role role);

// head against base; nullopt for a run, a failed scene, or a side without own peaks.
std::optional<MemorySummary> scene_memory(const SceneResult& scene);

struct MemoryJudgement {
  MemorySummary summary;
  ChangeVerdict verdict = ChangeVerdict::inconclusive;
  double limit = 0.0;  // the policy's max_memory_increase for the scene
};

std::optional<MemoryJudgement> judge_scene_memory(const SceneResult& scene,
                                                  const ScenePolicy& policy);

// How the own peaks of the document's revisions were measured (core/memory_cgroup.h), each
// method once, in the order of PeakMethod; empty when there are none.
std::vector<PeakMethod> peak_methods(const ResultsDocument& document);

// "12.3 MiB" (KiB in, binary units as the kernel counts them).
std::string memory_text(double kib);

// "head 58.3 MiB vs base 8.1 MiB (+50.2 MiB, +620%), limit +10%, 5 + 5 runs".
std::string describe_memory(const MemoryJudgement& judgement);

}  // namespace raygate

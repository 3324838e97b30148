// The profiles behind an explanation (issue 27). In sim mode every run already wrote cachegrind
// files, so a REGRESSED scene is explained from its first round's base and head runs at no
// extra cost (self cost only: cachegrind records no calls). In timed mode (`--explain`) base and
// head run once more each, under callgrind, for self and inclusive instructions: Valgrind counts
// without a PMU, which a VM rarely exposes, so the same explanation is possible on any CI
// runner; its cost is measured and stated.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "explain/explanation.h"
#include "runner/cachegrind.h"
#include "runner/contender.h"
#include "runner/executor.h"
#include "runner/scheduler.h"

namespace raygate {

// "valgrind-3.19.0 cachegrind, self cost": what a sim-mode explanation names as its profiler.
std::string profiler_name(const Cachegrind& cachegrind);
// "valgrind-3.19.0 callgrind, self and inclusive instructions": --explain's profiler.
std::string callgrind_profiler_name(const Cachegrind& valgrind);

// Sim mode: from the cachegrind files of the first complete round's `base` and `head` runs
// (<run dir>/cachegrind). nullopt when the scene has no such round; InfraError when the files
// cannot be read.
std::optional<Explanation> explain_simulated_runs(const SceneRuns& runs,
                                                  const Cachegrind& cachegrind);

// Timed mode: runs `base` and `head` once each on `scene` under callgrind, their files in
// `dir`/base and `dir`/head, and explains by instructions, self and inclusive.
// `native_seconds` is the two runs' measured time (without the profiler), kept beside the
// profiling's own seconds to state its cost. InfraError when a profiled run fails.
Explanation explain_by_profiling(const SceneInput& scene, const Contender& base,
                                 const Contender& head, const Cachegrind& cachegrind,
                                 const std::filesystem::path& dir, Executor& executor,
                                 double native_seconds);

// The median wall seconds of base's and of head's rounds, summed: the cost of one run each.
double native_pair_seconds(const SceneRuns& runs);

}  // namespace raygate

// A tracer revision as a contender: the adapter's run command with its placeholders filled in
// for this build and scene, in a fresh working directory, timed the way the adapter says
// (process wall or CPU seconds, or the time the tracer reports itself).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "adapter/adapter.h"
#include "adapter/placeholders.h"
#include "builder/build_record.h"
#include "runner/cachegrind.h"
#include "runner/contender.h"
#include "runner/timing/timing_mode.h"

namespace raygate {

struct TracerSetup {
  Role role = Role::tracer;
  Adapter adapter;
  BuildRecord build;                     // build_dir and src_dir come from here
  std::filesystem::path repo_root;       // the worktree
  std::filesystem::path raygate_source;  // {raygate_source}
  // How runs are timed (runner/timing/): the measurement's mode (--timing); null: the adapter's.
  const TimingMode* timing = nullptr;
  std::vector<int> cpus;  // pin runs to these CPUs; empty: no pinning
  // The longest one run may take: the adapter's run timeout bounded by the user's budget
  // (budgeted_run_seconds, measure/stopping_policy.h); 0: the adapter's alone.
  double run_timeout_seconds = 0.0;
  // The simulator, for an adapter timed by "simulated" (--timing sim); required then.
  std::optional<Cachegrind> cachegrind;
};

class TracerContender final : public Contender {
 public:
  explicit TracerContender(TracerSetup setup);

  ProcessSpec command(const SceneInput& scene, const std::filesystem::path& run_dir) const override;
  RunRecord interpret(const SceneInput& scene, const ProcessResult& result, const ProcessSpec& spec,
                      const std::filesystem::path& run_dir) const override;

  const TracerSetup& setup() const { return setup_; }
  const TimingMode& timing() const;

 private:
  Placeholders placeholders(const SceneInput& scene, const std::filesystem::path& run_dir) const;

  TracerSetup setup_;
};

}  // namespace raygate

#include "explain/explain_runs.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include "core/error.h"
#include "explain/callgrind_profile.h"

namespace raygate {
namespace {

const RunRecord* round_run(const Round& round, Role role) {
  const auto found = round.runs.find(role_name(role));
  return found == round.runs.end() ? nullptr : &found->second;
}

// A run's directory is where its log is (runner/tracer_contender.cpp: <run dir>/log.txt).
std::filesystem::path profile_dir(const RunRecord& run) {
  return cachegrind_dir(run.log.parent_path());
}

double median_wall(const SceneRuns& runs, Role role) {
  std::vector<double> walls;
  for (const Round& round : runs.rounds) {
    if (const RunRecord* run = round_run(round, role); run != nullptr) {
      walls.push_back(run->wall_seconds);
    }
  }
  if (walls.empty()) return 0.0;
  std::sort(walls.begin(), walls.end());
  const std::size_t n = walls.size();
  return n % 2 == 1 ? walls[n / 2] : 0.5 * (walls[n / 2 - 1] + walls[n / 2]);
}

// One run of `contender` under callgrind, its profile (self and inclusive) read back.
FunctionProfile profile_once(const SceneInput& scene, const Contender& contender,
                             const Cachegrind& valgrind, const std::filesystem::path& run_dir,
                             Executor& executor) {
  std::filesystem::remove_all(run_dir);
  std::filesystem::create_directories(run_dir);
  const std::filesystem::path out_dir = run_dir / "callgrind";
  ProcessSpec spec = under_callgrind(contender.command(scene, run_dir), valgrind, out_dir);
  // Valgrind runs a program some 30-100x slower than natively.
  if (spec.timeout.count() > 0) spec.timeout *= 100;
  const ProcessResult result = executor.run(spec);
  if (!result.succeeded()) {
    throw InfraError("--explain: " + contender.name() + " under callgrind " + result.describe() +
                     " (log: " + spec.stdout_path.string() + ")");
  }
  return read_callgrind_profiles(out_dir);
}

}  // namespace

std::string profiler_name(const Cachegrind& cachegrind) {
  return (cachegrind.version.empty() ? std::string("valgrind") : cachegrind.version) +
         " cachegrind, self cost";
}

std::string callgrind_profiler_name(const Cachegrind& valgrind) {
  return (valgrind.version.empty() ? std::string("valgrind") : valgrind.version) +
         " callgrind, self and inclusive instructions";
}

std::optional<Explanation> explain_simulated_runs(const SceneRuns& runs,
                                                  const Cachegrind& cachegrind) {
  for (const Round& round : runs.rounds) {
    const RunRecord* base = round_run(round, Role::base);
    const RunRecord* head = round_run(round, Role::head);
    if (base == nullptr || head == nullptr || !base->ok || !head->ok) continue;
    Explanation e = explain_change(read_function_profiles(profile_dir(*base)),
                                   read_function_profiles(profile_dir(*head)));
    e.source = ExplainSource::simulated_runs;
    e.profiler = profiler_name(cachegrind);
    return e;
  }
  return std::nullopt;
}

Explanation explain_by_profiling(const SceneInput& scene, const Contender& base,
                                 const Contender& head, const Cachegrind& valgrind,
                                 const std::filesystem::path& dir, Executor& executor,
                                 double native_seconds) {
  const auto started = std::chrono::steady_clock::now();
  const FunctionProfile base_profile =
      profile_once(scene, base, valgrind, dir / base.name(), executor);
  const FunctionProfile head_profile =
      profile_once(scene, head, valgrind, dir / head.name(), executor);
  Explanation e =
      explain_change(base_profile, head_profile, kExplainedFunctions, ExplainCost::instructions);
  e.source = ExplainSource::explain_runs;
  e.profiler = callgrind_profiler_name(valgrind);
  e.profile_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  e.native_seconds = native_seconds;
  return e;
}

double native_pair_seconds(const SceneRuns& runs) {
  return median_wall(runs, Role::base) + median_wall(runs, Role::head);
}

}  // namespace raygate

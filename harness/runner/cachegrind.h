// Running a contender under Valgrind's cachegrind for `--timing sim` (docs/simulated-timing.md),
// and reading back what it counted. Every process of a run (a wrapper script's children too)
// writes its own output file; a run's counters are their sum. The simulated caches have a fixed
// geometry, not the host's, so the same program costs the same on every machine.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/process.h"
#include "measure/simulated_cost.h"
#include "runner/run_record.h"
#include "runner/scheduler.h"

namespace raygate {

// The simulator as found on this machine: the command (looked up in PATH) and its version line
// ("valgrind-3.19.0"), which is part of every cached baseline cost's key.
struct Cachegrind {
  std::string command = "valgrind";
  std::string version;
};

// Asks `valgrind --version`. InfraError (exit 3) naming the Debian package when it is missing or
// does not answer: sim mode cannot measure anything without it.
Cachegrind find_cachegrind();

// `spec` to run under cachegrind, its output files in `out_dir` (created), one per process.
ProcessSpec under_cachegrind(ProcessSpec spec, const Cachegrind& cachegrind,
                             const std::filesystem::path& out_dir);

// The totals of one cachegrind output file (its "events:" and "summary:" lines). Throws
// InfraError naming origin:line when either is missing, they disagree in length, or an event
// the cost model needs is absent (a run without --cache-sim=yes).
SimulatedCounters parse_cachegrind_output(std::string_view text, const std::string& origin);

// The sum over every output file in `out_dir`; InfraError if there is none.
SimulatedCounters read_cachegrind_outputs(const std::filesystem::path& out_dir);

// For a run that succeeded: its counters from `out_dir` into run.simulated, and run.seconds
// their estimated cycles. Output that cannot be read fails the run (ok = false, the reason).
void record_simulated_cost(RunRecord& run, const std::filesystem::path& out_dir);

// Whether the simulated counts repeated, for the line of a scene measured in sim mode:
// "simulated cycles, counts repeat exactly" or "simulated cycles differ between runs (spread:
// head 0.0132%): timed statistics"; "" when no run was simulated.
std::string determinism_note(const SceneRuns& runs);

// Where a run's cachegrind files go: a folder of its run directory.
std::filesystem::path cachegrind_dir(const std::filesystem::path& run_dir);

}  // namespace raygate

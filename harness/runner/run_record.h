// The record of one timed run of one contender (the baseline, or a tracer revision) on one scene:
// how the process ended, its times, and where its image and log are. A run that failed is data
// here (ok = false with the reason), exactly as a run that succeeded.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "core/process.h"
#include "measure/simulated_cost.h"

namespace raygate {

// One reading a timing mode recorded besides the process's own times (runner/timing/
// timing_mode.h CounterSpec): its value and unit, as the mode registered them.
struct Counter {
  double value = 0.0;
  std::string unit;  // "seconds", "cycles", "instructions"
  bool operator==(const Counter&) const = default;
};

// Its ProcessUsage is the process's, as it ended. Documents from before raygate-meter have no
// own peaks (max_rss_own false), and those from before issue 40 peak_method largest_process.
struct RunRecord : ProcessUsage {
  bool ok = false;
  std::string outcome;   // ProcessResult::describe(): "exited with status 0", "killed by SIGSEGV"
  std::string failure;   // why the run is unusable, one line; empty when ok
  double seconds = 0.0;  // the time the ratio uses (see TimeSource in contender.h)
  // The contender's own account of its time, when it gives one: the baseline's parse + prepare +
  // render seconds from --stats, or a tracer's time parsed with the adapter's regex.
  std::optional<double> reported_seconds;
  // --timing sim: cachegrind's counters of the run (seconds then holds their estimated cycles).
  std::optional<SimulatedCounters> simulated;
  // Readings the timing mode added (TimingMode::collect), by the counter's name: the reported
  // mode's startup_seconds, say. Checked against the registry's counters when read.
  std::map<std::string, Counter> counters;
  std::filesystem::path image;
  std::filesystem::path log;  // stdout and stderr together
  // Timed out before its own limit (the adapter's timeout_s.run): raygate's time budget
  // (--max-seconds, --max-minutes) ended it, so the run says nothing of the revision, and a
  // compare whose head it was could not be measured (exit 3), not regressed.
  bool stopped_by_budget = false;

  bool operator==(const RunRecord&) const = default;
};

void to_json(nlohmann::json& json, const RunRecord& run);
void from_json(const nlohmann::json& json, RunRecord& run);

}  // namespace raygate

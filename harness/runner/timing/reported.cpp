// The time a tracer prints itself (the adapter's timing.regex), against the baseline's own
// parse + prepare + render seconds from --stats: neither counts its process start-up
// (DESIGN.md §11). Both contenders put that number in RunRecord::reported_seconds. What the
// reported time leaves out is still recorded: each run's start-up, its process wall seconds
// minus the reported ones, as the counter startup_seconds, so a report shows how much of the
// process the ratio no longer sees (Blender: about a second of start-up around a short render).
#include <algorithm>

#include "runner/timing/timing_mode.h"

namespace raygate {
namespace {

constexpr CounterSpec kStartup{
    "startup_seconds", "seconds",
    "process wall seconds minus the reported seconds: start-up, scene loading, shutdown"};

void record_startup(RunRecord& run) {
  if (!run.reported_seconds) return;
  // A tracer's clock and wait4's are read at different moments: a render reported as a little
  // longer than its process is start-up 0, not a negative one.
  const double startup = std::max(0.0, run.wall_seconds - *run.reported_seconds);
  run.counters[std::string(kStartup.name)] = {startup, std::string(kStartup.unit)};
}

}  // namespace

std::unique_ptr<TimingMode> make_reported_mode() {
  return make_clock_mode({"reported",
                          "reported by the tracer",
                          "reported",
                          "in-process",
                          [](const RunRecord& run) { return run.reported_seconds; },
                          TimingSource::reported,
                          {kStartup},
                          record_startup});
}

}  // namespace raygate

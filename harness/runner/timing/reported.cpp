// The time a tracer prints itself (the adapter's timing.regex), against the baseline's own
// parse + prepare + render seconds from --stats: neither counts its process start-up
// (DESIGN.md §11). Both contenders put that number in RunRecord::reported_seconds.
#include "runner/timing/timing_mode.h"

namespace raygate {

std::unique_ptr<TimingMode> make_reported_mode() {
  return make_clock_mode({"reported", "reported by the tracer", "reported", "in-process",
                          [](const RunRecord& run) { return run.reported_seconds; },
                          TimingSource::reported});
}

}  // namespace raygate

// The default clock: wall seconds of the whole process, fork to wait4, on both sides. The only
// clock that shows a multi-threaded tracer's parallel speed-up.
#include "runner/timing/timing_mode.h"

namespace raygate {

std::unique_ptr<TimingMode> make_process_wall_mode() {
  return make_clock_mode(
      {"wall", "process wall-clock seconds (wait4)", "process-wall", "process-wall",
       [](const RunRecord& run) -> std::optional<double> { return run.wall_seconds; }});
}

}  // namespace raygate

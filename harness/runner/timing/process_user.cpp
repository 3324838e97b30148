// User CPU seconds only (wait4's ru_utime), on both sides. System time is the kernel's work for
// the process: page faults, reading the scene, writing the image. It varies with the page cache
// and the file system, not with the tracer's code, so leaving it out keeps a change in the
// tracer's own instructions from drowning in the kernel's noise.
#include "runner/timing/timing_mode.h"

namespace raygate {

std::unique_ptr<TimingMode> make_process_user_mode() {
  return make_clock_mode(
      {"user", "process user CPU seconds, without system time (wait4)", "process-user",
       "process-user",
       [](const RunRecord& run) -> std::optional<double> { return run.user_seconds; }});
}

}  // namespace raygate

// User + system CPU seconds of the whole process (wait4's rusage), on both sides: a busy runner
// does not inflate it by the time a one-thread tracer waits for a CPU.
#include "runner/timing/timing_mode.h"

namespace raygate {

std::unique_ptr<TimingMode> make_process_cpu_mode() {
  return make_clock_mode(
      {"cpu", "process CPU seconds, user + system (wait4)", "process-cpu", "process-cpu",
       [](const RunRecord& run) -> std::optional<double> { return run.cpu_seconds(); }});
}

}  // namespace raygate

// User + system CPU seconds of the whole process (wait4's rusage), on both sides: a busy runner
// does not inflate it by the time a one-thread tracer waits for a CPU.
#include <memory>

#include "runner/timing/timing_mode.h"

namespace raygate {
namespace {

class ProcessCpu final : public TimingMode {
 public:
  std::string_view name() const override { return "cpu"; }
  std::string_view description() const override {
    return "process CPU seconds, user + system (wait4)";
  }
  std::string_view tracer_clock() const override { return "process-cpu"; }
  std::string_view baseline_clock() const override { return "process-cpu"; }
  std::optional<double> seconds(const RunRecord& run) const override { return run.cpu_seconds(); }
};

}  // namespace

std::unique_ptr<TimingMode> make_process_cpu_mode() { return std::make_unique<ProcessCpu>(); }

}  // namespace raygate

// User CPU seconds only (wait4's ru_utime), on both sides. System time is the kernel's work for
// the process: page faults, reading the scene, writing the image. It varies with the page cache
// and the file system, not with the tracer's code, so leaving it out keeps a change in the
// tracer's own instructions from drowning in the kernel's noise.
#include <memory>

#include "runner/timing/timing_mode.h"

namespace raygate {
namespace {

class ProcessUser final : public TimingMode {
 public:
  std::string_view name() const override { return "user"; }
  std::string_view description() const override {
    return "process user CPU seconds, without system time (wait4)";
  }
  std::string_view tracer_clock() const override { return "process-user"; }
  std::string_view baseline_clock() const override { return "process-user"; }
  std::optional<double> seconds(const RunRecord& run) const override { return run.user_seconds; }
};

}  // namespace

std::unique_ptr<TimingMode> make_process_user_mode() { return std::make_unique<ProcessUser>(); }

}  // namespace raygate

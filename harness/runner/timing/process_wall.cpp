// The default clock: wall seconds of the whole process, fork to wait4, on both sides. The only
// clock that shows a multi-threaded tracer's parallel speed-up.
#include <memory>

#include "runner/timing/timing_mode.h"

namespace raygate {
namespace {

class ProcessWall final : public TimingMode {
 public:
  std::string_view name() const override { return "wall"; }
  std::string_view description() const override { return "process wall-clock seconds (wait4)"; }
  std::string_view tracer_clock() const override { return "process-wall"; }
  std::string_view baseline_clock() const override { return "process-wall"; }
  std::optional<double> seconds(const RunRecord& run) const override { return run.wall_seconds; }
};

}  // namespace

std::unique_ptr<TimingMode> make_process_wall_mode() { return std::make_unique<ProcessWall>(); }

}  // namespace raygate

// The time a tracer prints itself (the adapter's timing.regex), against the baseline's own
// parse + prepare + render seconds from --stats: neither counts its process start-up
// (DESIGN.md §11). Both contenders put that number in RunRecord::reported_seconds.
#include <memory>

#include "runner/timing/timing_mode.h"

namespace raygate {
namespace {

class Reported final : public TimingMode {
 public:
  std::string_view name() const override { return "reported"; }
  std::string_view description() const override { return "reported by the tracer"; }
  std::string_view tracer_clock() const override { return "reported"; }
  std::string_view baseline_clock() const override { return "in-process"; }
  TimingSource source() const override { return TimingSource::reported; }
  bool command_line_choice() const override { return false; }
  std::optional<double> seconds(const RunRecord& run) const override {
    return run.reported_seconds;
  }
};

}  // namespace

std::unique_ptr<TimingMode> make_reported_mode() { return std::make_unique<Reported>(); }

}  // namespace raygate

#include "runner/timing/timing_modes.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <memory>

#include "core/error.h"

namespace raygate {

// Each factory is defined in its mode's own file.
#define RAYGATE_TIMING_MODE(factory) std::unique_ptr<TimingMode> factory();
#include "runner/timing/modes.def"
#undef RAYGATE_TIMING_MODE

namespace {

class ClockMode final : public TimingMode {
 public:
  explicit ClockMode(const ClockSpec& spec) : spec_(spec) {}
  std::string_view name() const override { return spec_.name; }
  std::string_view description() const override { return spec_.description; }
  std::string_view tracer_clock() const override { return spec_.tracer_clock; }
  std::string_view baseline_clock() const override { return spec_.baseline_clock; }
  TimingSource source() const override { return spec_.source; }
  // A time the tracer prints needs the adapter's regex: not a command-line choice.
  bool command_line_choice() const override { return spec_.source == TimingSource::process; }
  std::optional<double> seconds(const RunRecord& run) const override { return spec_.seconds(run); }
  std::vector<CounterSpec> counters() const override { return spec_.counters; }
  void collect(RunRecord& run, const std::filesystem::path& /*run_dir*/) const override {
    if (spec_.derive != nullptr) spec_.derive(run);
  }

 private:
  ClockSpec spec_;
};

std::vector<std::unique_ptr<TimingMode>> make_modes() {
  std::vector<std::unique_ptr<TimingMode>> modes;
#define RAYGATE_TIMING_MODE(factory) modes.push_back(factory());
#include "runner/timing/modes.def"
#undef RAYGATE_TIMING_MODE
  return modes;
}

std::vector<std::string> names(bool command_line_only) {
  std::vector<std::string> out;
  for (const TimingMode* mode : timing_modes()) {
    if (!command_line_only || mode->command_line_choice()) out.emplace_back(mode->name());
  }
  return out;
}

}  // namespace

std::unique_ptr<TimingMode> make_clock_mode(const ClockSpec& spec) {
  return std::make_unique<ClockMode>(spec);
}

const std::vector<const TimingMode*>& timing_modes() {
  // Built once, never changed: the modes are stateless, so this is a constant table.
  static const std::vector<std::unique_ptr<TimingMode>> owned = make_modes();
  static const std::vector<const TimingMode*> modes = [] {
    std::vector<const TimingMode*> out;
    for (const auto& mode : owned) out.push_back(mode.get());
    return out;
  }();
  return modes;
}

const TimingMode& timing_mode(std::string_view name) {
  for (const TimingMode* mode : timing_modes()) {
    if (mode->name() == name) return *mode;
  }
  throw UsageError(
      fmt::format("unknown timing mode '{}' (known: {})", name, fmt::join(names(false), ", ")));
}

std::vector<std::string> timing_mode_choices() { return names(true); }

std::string timing_choices_help() {
  std::string help = "how runs are timed, both sides by the same clock:";
  for (const TimingMode* mode : timing_modes()) {
    if (!mode->command_line_choice()) continue;
    help += fmt::format(" {}: {};", mode->name(), mode->description());
  }
  return help + " (default: the adapter's)";
}

const TimingMode& adapter_timing_mode(const Timing& timing) {
  for (const TimingMode* mode : timing_modes()) {
    if (mode->source() != timing.source) continue;
    if (timing.source != TimingSource::process || mode->name() == to_string(timing.metric)) {
      return *mode;
    }
  }
  throw std::logic_error(fmt::format("no timing mode for source {} metric {}",
                                     to_string(timing.source), to_string(timing.metric)));
}

const TimingMode& resolve_timing_mode(const Timing& adapter_timing, std::string_view choice) {
  // Sweep 12: `--timing wall` on an adapter that reports its time was dropped without a word
  // (and the document recorded a metric never used); --timing is the user's, for both sides.
  if (choice.empty()) return adapter_timing_mode(adapter_timing);
  return timing_mode(choice);
}

}  // namespace raygate

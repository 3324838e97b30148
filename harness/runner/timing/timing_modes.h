// The registry of timing modes (timing_mode.h): every mode listed in modes.def, found by the
// name `--timing` and adapter files use, or by an adapter's timing section.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "adapter/adapter.h"
#include "runner/timing/timing_mode.h"

namespace raygate {

// Every mode, in the order of modes.def. They live as long as the program.
const std::vector<const TimingMode*>& timing_modes();

// The mode called `name`; UsageError listing the names (with "did you mean") otherwise.
const TimingMode& timing_mode(std::string_view name);

// The names --timing offers, in registry order, and its help: one clause per mode.
std::vector<std::string> timing_mode_choices();
std::string timing_choices_help();

// The mode an adapter's timing section names: its process clock by the metric's word, or the
// one mode of a reported or simulated source.
const TimingMode& adapter_timing_mode(const Timing& timing);

// The mode of a measurement: `choice` (--timing; "" = none) or the adapter's. A choice replaces
// any source: `--timing wall` times a tracer that reports its own time by its process's wall
// clock, start-up and all.
const TimingMode& resolve_timing_mode(const Timing& adapter_timing, std::string_view choice);

}  // namespace raygate

// The text fields shared by valgrind's two profile formats (cachegrind's and callgrind's): a
// line's whitespace-separated fields, and which simulated counter an event name fills.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "measure/simulated_cost.h"

namespace raygate {

// The whitespace-separated fields of one line of a profile file.
std::vector<std::string_view> profile_fields(std::string_view line);

// The counter an event name ("Ir", "D1mr", ...) is; nullptr for an event the cost model does
// not use (branch simulation), which is not kept.
std::uint64_t* counter_named(SimulatedCounters& counters, std::string_view event);

}  // namespace raygate

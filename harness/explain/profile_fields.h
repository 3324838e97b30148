// The text shared by valgrind's two profile formats (cachegrind's and callgrind's): feeding a
// file's lines to its reader, a line's whitespace-separated fields, and which simulated counter
// an event name fills.
#pragma once

#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "measure/simulated_cost.h"

namespace raygate {

// Gives each line of `text` to a Reader made for `origin` (the file named in its errors), with
// its number from 1, and returns the reader's finish(): both formats are read a line at a time,
// each by a reader that keeps the state its format's compressed lines refer back to.
template <typename Reader>
auto read_profile_lines(std::string_view text, const std::string& origin) {
  Reader reader(origin);
  std::istringstream in{std::string(text)};
  int number = 0;
  for (std::string line; std::getline(in, line);) reader.line(line, ++number);
  return reader.finish();
}

// The whitespace-separated fields of one line of a profile file.
std::vector<std::string_view> profile_fields(std::string_view line);

// The counter an event name ("Ir", "D1mr", ...) is; nullptr for an event the cost model does
// not use (branch simulation), which is not kept.
std::uint64_t* counter_named(SimulatedCounters& counters, std::string_view event);

}  // namespace raygate

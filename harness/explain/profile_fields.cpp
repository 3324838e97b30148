#include "explain/profile_fields.h"

namespace raygate {

std::vector<std::string_view> profile_fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t at = 0;
  while (at < line.size()) {
    const std::size_t start = line.find_first_not_of(" \t\r", at);
    if (start == std::string_view::npos) break;
    const std::size_t end = line.find_first_of(" \t\r", start);
    out.push_back(line.substr(start, end == std::string_view::npos ? end : end - start));
    at = end == std::string_view::npos ? line.size() : end;
  }
  return out;
}

std::uint64_t* counter_named(SimulatedCounters& c, std::string_view event) {
  if (event == "Ir") return &c.ir;
  if (event == "I1mr") return &c.i1mr;
  if (event == "ILmr") return &c.ilmr;
  if (event == "Dr") return &c.dr;
  if (event == "D1mr") return &c.d1mr;
  if (event == "DLmr") return &c.dlmr;
  if (event == "Dw") return &c.dw;
  if (event == "D1mw") return &c.d1mw;
  if (event == "DLmw") return &c.dlmw;
  return nullptr;
}

}  // namespace raygate

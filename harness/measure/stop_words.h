// Why a scene stopped, in words a reader of the progress lines and the HTML report understands.
// The results document keeps the identifiers (to_string(StopDecision), measure/stopping_policy.h);
// these are only what is printed.
#pragma once

#include <string>
#include <string_view>

#include "measure/stopping_policy.h"

namespace raygate {

inline std::string stop_reason_text(std::string_view stop_reason) {
  if (stop_reason == to_string(StopDecision::stop_converged)) return "decided";
  if (stop_reason == to_string(StopDecision::stop_budget_rounds)) {
    return "stopped at its round limit";
  }
  if (stop_reason == to_string(StopDecision::stop_budget_time)) {
    return "stopped at its share of the time";
  }
  return std::string(stop_reason);  // "failed", and words of a newer raygate, as they are
}

}  // namespace raygate

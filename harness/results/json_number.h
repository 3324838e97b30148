// A double as JSON: the value, or null when it is not finite (JSON has no NaN or infinity). One
// rule for the results document and every JSON raygate writes from it.
#pragma once

#include <cmath>

#include <nlohmann/json.hpp>

namespace raygate {

inline nlohmann::json finite_number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

}  // namespace raygate

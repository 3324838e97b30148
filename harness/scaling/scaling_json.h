// The scaling analysis at the JSON boundary: the `scaling` member of a results document
// (docs/results-format.md), read back by `raygate report` and `raygate scaling`.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "scaling/scaling_analysis.h"

namespace raygate {

nlohmann::json to_json(const ScalingAnalysis& analysis);
// Throws UsageError naming `origin` and what is wrong for JSON that is not a scaling analysis.
ScalingAnalysis scaling_from_json(const nlohmann::json& json, const std::string& origin);

}  // namespace raygate

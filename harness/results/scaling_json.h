// The scaling analysis at the JSON boundary: the `scaling` member of a results document
// (docs/results-format.md). results_json.cpp reads it once, with the document; everything else
// reads ResultsDocument::scaling (results/scaling_record.h).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/json_field.h"
#include "results/scaling_record.h"

namespace raygate {

nlohmann::json to_json(const ScalingAnalysis& analysis);
// Throws FieldError with the JSONPath of what is wrong ("$.scaling.families[0].points").
ScalingAnalysis scaling_from_json(const JsonField& field);

}  // namespace raygate

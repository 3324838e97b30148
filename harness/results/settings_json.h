// The settings of a results document at the JSON boundary (docs/results-format.md, "settings"):
// the typed record (results/measurement_settings.h) written as the flat object documents have
// always had, and read back with the JSONPath of a wrong value in the error.
#pragma once

#include <nlohmann/json.hpp>

#include "core/json_field.h"
#include "results/measurement_settings.h"

namespace raygate {

// Only the fields that are set, plus the unknown keys as they were read: a document reads and
// writes back to the same object.
nlohmann::json to_json(const MeasurementSettings& settings);

// An object, or null (a document built without settings): read as no settings. Throws
// FieldError naming the path ("$.settings.threads: expected a whole number ...").
MeasurementSettings settings_from_json(const JsonField& field);

std::string_view to_string(PinnedBy pinned_by);
std::string_view to_string(CpuIdle idle);

}  // namespace raygate

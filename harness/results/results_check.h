// The whole check of a results document read from disk (gate, report, import, merge, history,
// scaling, consistency, shard costs, golden bless --from-run). Such a document is untrusted
// input: a hand-edited or forged file with `kind: "weird"`, a scene `status: "exploded"` or one
// scene listed twice would otherwise be gated, reported and stored as if it were measured.
// Every field the reader takes is checked here for its type, its known words and a finite
// number in range, before any of it is converted; the first problem is thrown with its JSON path.
#pragma once

#include <nlohmann/json.hpp>

#include "runner/timing/timing_check.h"

namespace raygate {

// Throws FieldError (core/json_field.h) naming the JSON path of the first problem.
// Unknown members are allowed (a newer raygate of the same schema_version may add some); the
// schema_version itself is checked by the caller, which words a newer one differently.
void check_results_json(const nlohmann::json& document);
// The same against `modes` instead of the registry's (a test's extra mode): the timing parts
// are checked from the modes (runner/timing/timing_check.h), nothing else depends on them.
void check_results_json(const nlohmann::json& document, const TimingModeList& modes);

}  // namespace raygate

// How `raygate consistency` shows its result: a terminal table (documents, r² per pair,
// per-scene ratios and deviations, unstable and missing scenes, the verdict), the same as JSON
// for machines, and as Markdown for a wiki page or a CI summary.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "consistency/consistency.h"

namespace raygate {

std::string consistency_table(const ConsistencyResult& result);
nlohmann::json consistency_json(const ConsistencyResult& result);
std::string consistency_markdown(const ConsistencyResult& result);

}  // namespace raygate

// JSON form of what measuring and image checks summarize: intervals, a scene's normalized
// ratio, the suite score, a compare's change and an image comparison's metrics. Part of the
// results document's public schema (docs/results-format.md); nlohmann::json finds these by
// argument-dependent lookup wherever a document is written or read.
#pragma once

#include <nlohmann/json.hpp>

#include "compare/image_compare.h"
#include "compare/noisy_image_compare.h"
#include "measure/bootstrap.h"
#include "measure/change.h"
#include "measure/ratio.h"

namespace raygate {

void to_json(nlohmann::json& j, const Interval& interval);
void from_json(const nlohmann::json& j, Interval& interval);
void to_json(nlohmann::json& j, const RatioSummary& r);
void from_json(const nlohmann::json& j, RatioSummary& r);
void to_json(nlohmann::json& j, const SuiteScore& s);
void from_json(const nlohmann::json& j, SuiteScore& s);
void to_json(nlohmann::json& j, const ChangeSummary& c);
void from_json(const nlohmann::json& j, ChangeSummary& c);
void to_json(nlohmann::json& j, const ImageMetrics& m);
void from_json(const nlohmann::json& j, ImageMetrics& m);
// A Monte Carlo image comparison (images[].monte_carlo): verdict, tolerance, intervals, biased
// tiles, what more samples would decide. Read after results_check.cpp checked it.
void to_json(nlohmann::json& j, const NoisyComparison& c);
void from_json(const nlohmann::json& j, NoisyComparison& c);

}  // namespace raygate

// Counting primitives regenerates scenes, so one cache serves the fit and the projection.
#include "scaling/scaling_stage.h"

#include <fmt/core.h>

#include "scaling/primitive_count.h"
#include "scaling/scaling_json.h"
#include "scaling/scaling_text.h"

namespace raygate {

ScalingAnalysis attach_scaling(ResultsDocument& document, const ScalingLimits& limits,
                               std::FILE* out) {
  CachedPrimitiveCount counts;
  const ScalingAnalysis analysis = analyse_scaling(
      document, limits, [&](const std::string& scene, int size) { return counts(scene, size); });
  if (analysis.families.empty()) return analysis;
  document.scaling = to_json(analysis);
  if (out == nullptr) return analysis;  // --quiet
  for (const std::string& line : scaling_lines(analysis)) fmt::print(out, "{}\n", line);
  return analysis;
}

}  // namespace raygate

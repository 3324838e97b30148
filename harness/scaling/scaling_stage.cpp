// Counting primitives regenerates scenes, so one cache serves the fit and the projection.
#include "scaling/scaling_stage.h"

#include "scaling/primitive_count.h"

namespace raygate {

ScalingAnalysis attach_scaling(ResultsDocument& document, const ScalingLimits& limits) {
  CachedPrimitiveCount counts;
  const ScalingAnalysis analysis = analyse_scaling(
      document, limits, [&](const std::string& scene, int size) { return counts(scene, size); });
  if (analysis.families.empty()) return analysis;
  document.scaling = analysis;
  return analysis;
}

}  // namespace raygate

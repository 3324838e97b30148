// The scaling stage of run and compare: after the suite is measured, fit each scene family's
// growth, print it, and keep it in the results document (and so in the store).
#pragma once

#include <cstdio>

#include "scaling/scaling_analysis.h"
#include "store/results.h"

namespace raygate {

// Sets document.scaling and prints the fits to `out` when some family was measured at 3 sizes
// or more (nothing printed when `out` is null: --quiet); leaves the document alone otherwise.
// Returns the analysis.
ScalingAnalysis attach_scaling(ResultsDocument& document, const ScalingLimits& limits,
                               std::FILE* out);

}  // namespace raygate

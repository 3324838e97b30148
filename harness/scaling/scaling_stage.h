// The scaling stage of run and compare: after the suite is measured, fit each scene family's
// growth and keep it in the results document (and so in the store); scaling/scaling_text.h
// says it in lines.
#pragma once

#include "scaling/scaling_analysis.h"
#include "results/results.h"

namespace raygate {

// Sets document.scaling when some family was measured at 3 sizes or more; leaves the document
// alone otherwise. Returns the analysis (no families: nothing to say).
ScalingAnalysis attach_scaling(ResultsDocument& document, const ScalingLimits& limits);

}  // namespace raygate

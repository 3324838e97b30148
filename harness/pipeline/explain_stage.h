// The explanation step of a compare (issue 27): after the verdicts (and the family's Holm
// control), each scene whose speed REGRESSED gets the functions whose cost grew most. Sim mode
// reads the cachegrind files its runs already wrote; timed mode profiles base and head once
// each under callgrind, and only with --explain. Scenes that did not regress cost nothing.
#pragma once

#include <string>
#include <vector>

#include "pipeline/measure_context.h"
#include "pipeline/suite_measurement.h"
#include "results/results.h"
#include "runner/contender.h"
#include "runner/executor.h"

namespace raygate {

// Fills scene.explanation for the REGRESSED scenes; returns lines for the measurement's account
// ("explained 1 regressed scene with valgrind-3.19.0 cachegrind in 12.3 s"). A profile that
// cannot be read or a profiled run that fails is said in a line, not fatal: the verdict stands.
std::vector<std::string> explain_regressed_scenes(ResultsDocument& document,
                                                  const MeasureContext& context,
                                                  const SuiteMeasurement& m, const Contender& base,
                                                  const Contender& head, Executor& executor);

}  // namespace raygate

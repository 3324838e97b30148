// How noisy the runner was, said as a note of the gate when a compare left a scene INCONCLUSIVE:
// the spread of the rounds (head/base per round) and what it would have had to be below for the
// rounds the scenes got to decide them. A VM whose host is busy shows nothing in the load
// average or steal time, so the compare measures the noise itself; every report that prints the
// gate's notes (console, Markdown, the closing lines of a CI log) says it.
#pragma once

#include <optional>
#include <string>

#include "gate/policy.h"
#include "results/results.h"

namespace raygate {

// "runner noise: the rounds of a scene differed by 5.8% (head/base per round, scaled MAD, median
// of 13 scenes); in the 18 rounds a scene typically got, an unchanged scene is shown within the
// 3.0% limit (UNCHANGED) only when its rounds differ by less than about 3.5%. A quieter runner,
// ..." when some scene measured on
// confidence sequences is INCONCLUSIVE; nullopt otherwise (all decided, a run, sim mode, or a
// document from before confidence sequences).
std::optional<std::string> runner_noise_note(const ResultsDocument& document,
                                             const GatePolicy& policy);

}  // namespace raygate

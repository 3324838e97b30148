// The scaling analysis as lines of text, for the terminal, `raygate scaling` and the markdown
// report: one line per fit, with the exponent, its interval, r² and what the diagnosis means.
#pragma once

#include <string>
#include <vector>

#include "scaling/scaling_analysis.h"

namespace raygate {

// "k 0.98 [0.95, 1.01], r² 0.999, power law" and, when it is not one, why.
std::string describe_fit(const PowerFit& fit);

// "exponent head - base +0.62 [+0.55, +0.70] (limit +0.10): REGRESSED; at balls size 4 ..."
std::string describe_change(const std::string& family, const ExponentChange& change);

std::vector<std::string> scaling_lines(const ScalingAnalysis& analysis);

}  // namespace raygate

// A normalized ratio as people read it: "0.512 [0.508, 0.516]" (its 95% interval), or, from a
// single round, "0.940 (1 round: no interval)": one round has no spread, and printing its value
// twice as an interval showed a zero-width "95% CI" (the sweep of 2026-11-28).
#pragma once

#include <string>

#include "measure/ratio.h"

namespace raygate {

std::string ratio_interval_text(const RatioSummary& ratio);

}  // namespace raygate

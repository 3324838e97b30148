// The line a report prints for the counters a timing mode recorded beside each run's measure
// (RunRecord::counters): per counter and role, its median over the scenes' rounds, with its
// unit, and for a counter in seconds its share of the process's wall time. So a run timed by
// the tracer's reported seconds still shows the start-up it left out (the reported mode's
// startup_seconds), and a new mode's counter is printed without a line of report code.
#pragma once

#include <string>

#include "results/results.h"

namespace raygate {

// "startup_seconds (median per run): baseline 0.004 s (1% of its process wall time), tracer
// 0.951 s (79% of its process wall time)"; "" when no run carries a counter.
std::string counters_line(const ResultsDocument& document);

}  // namespace raygate

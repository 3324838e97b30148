// The one check of the timing parts of a results document read from disk, from the registry the
// modes come from (timing_modes.h): the clock names (baseline.timing, settings.tracer_clock and
// baseline_clock), the measure's unit (settings.unit), and every counter a run carries (its
// name one a mode declares, its unit that mode's, its value finite and in range). A new mode's
// words and counters are therefore known here by registering the mode, with no second list.
#pragma once

#include <string>
#include <vector>

#include "core/json_field.h"
#include "runner/timing/timing_mode.h"

namespace raygate {

// The modes a document is checked against; timing_modes() unless a caller (a test) adds some.
using TimingModeList = std::vector<const TimingMode*>;

// Every clock name a document may carry: each mode's tracer and baseline clock, and the names
// of clocks documents carried before the clocks were matched (issue 18: "in-process-cpu").
std::vector<std::string> known_clock_names(const TimingModeList& modes);

// The timing parts of a whole results document (results/results_check.cpp calls it once, after
// the document's shape is checked): baseline.timing; settings.tracer_clock, baseline_clock and
// unit, each when present (older documents lack them); and the "counters" of every run, in the
// warm-ups, the rounds, a partial round and a failure. Throws FieldError naming the JSON path
// and the words it knows.
void check_document_timing(const JsonField& document, const TimingModeList& modes);

// The parts, for a caller that holds one.
void check_clock_name(const JsonField& field, const TimingModeList& modes);
void check_run_counters(const JsonField& counters, const TimingModeList& modes);

}  // namespace raygate

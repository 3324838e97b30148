// The gate's verdict as plain lines on a stream: one line per scene that is not a clean pass
// (failures first, each with its reasons), then one summary line. What every measuring command
// prints last, so the end of a CI log says what happened.
#pragma once

#include <cstdio>

#include "gate/verdict.h"

namespace raygate {

void print_gate_summary(const GateResult& gate, std::FILE* stream);

}  // namespace raygate

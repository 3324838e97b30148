// What `--timing sim` (or an adapter timed "simulated") changes in a measurement
// (docs/simulated-timing.md): every run under cachegrind, no warm-ups (counting needs no warm
// caches), two rounds to check that the counts repeat, its own default limit, the baseline's
// cost cached per scene, and a warning for multi-threaded tracers, which valgrind serializes.
#pragma once

#include <string>

#include "cli/measure_options.h"
#include "runner/baseline_contender.h"

namespace raygate::cli {

// The default max_slowdown without a policy file: a counted change needs no noise margin, but
// the model is an estimate of cycles, not cycles, so 1% rather than 0.
inline constexpr double kSimulatedDefaultLimit = 0.01;

bool simulated(const MeasureContext& context);

// Switches the context to sim mode when --timing sim asks or the adapter is timed "simulated";
// finds valgrind (InfraError if it is missing). Leaves any other context untouched.
void apply_simulated_mode(const MeasureArgs& args, MeasureContext& context);

// The baseline contender of a measurement, timed by the tracer's clock; in sim mode simulated
// under cachegrind with its costs cached in <cache-dir>/simulated-baseline.
BaselineContender make_baseline_contender(const MeasureContext& context,
                                          const std::string& baseline_source_sha256);

}  // namespace raygate::cli

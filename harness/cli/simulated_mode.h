// What `--timing sim` (or an adapter timed "simulated") changes in a measurement
// (docs/simulated-timing.md): every run under cachegrind, no warm-ups (counting needs no warm
// caches), two rounds to check that the counts repeat, its own default limit, the baseline's
// cost cached per scene, and a warning for multi-threaded tracers, which valgrind serializes.
#pragma once

#include "cli/measure_options.h"

namespace raygate::cli {

// The default max_slowdown without a policy file: a counted change needs no noise margin, but
// the model is an estimate of cycles, not cycles, so 1% rather than 0.
inline constexpr double kSimulatedDefaultLimit = 0.01;

// Switches the context to sim mode when --timing sim asks or the adapter is timed "simulated";
// finds valgrind (InfraError if it is missing). Leaves any other context untouched.
void apply_simulated_mode(const MeasureArgs& args, MeasureContext& context);

}  // namespace raygate::cli

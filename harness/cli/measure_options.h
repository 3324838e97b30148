// Command-line options shared by the commands that measure (run, compare, bisect): where the
// tracer is, how to build it, which scenes, and the schedule and stopping policy. One place, so
// every measuring command spells its flags the same way.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "pipeline/measure_options.h"

namespace raygate::cli {

// The options bind straight into the pipeline's record of them (pipeline/measure_options.h).
using MeasureArgs = MeasureOptions;

// Where the tracer is and which scenes of which suite: --repo, --adapter (required), --suite,
// --scene, --cache-dir, --baseline, --jobs. Every command that builds a tracer takes them.
void add_tracer_options(CLI::App& command, MeasureArgs& args);

// run's: where the tracer is, how to build it, which scenes, the schedule and stopping policy.
void add_measure_options(CLI::App& command, MeasureArgs& args);

// compare's and bisect's: the measure options with the change's stopping policy and baseline
// rounds as defaults (measure/stopping_policy.h), and --baseline-rounds (the change of head against
// base needs no baseline; the normalized ratios need a few).
void add_change_measure_options(CLI::App& command, MeasureArgs& args);

// --shard K/N and --shard-costs: for run and compare, whose documents `raygate merge` joins.
void add_shard_options(CLI::App& command, MeasureArgs& args);

// load_measure_context (pipeline/measure_options.h), its warnings said on standard error.
MeasureContext load_measure_context(const MeasureArgs& args);

}  // namespace raygate::cli

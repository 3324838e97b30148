// Command-line options shared by the commands that measure (run, compare, bisect): where the
// tracer is, how to build it, which scenes, and the schedule and stopping policy. One place, so
// every measuring command spells its flags the same way.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include "measure/stopping.h"
#include "pipeline/measure_context.h"

namespace raygate::cli {

struct MeasureArgs {
  std::string repo = ".";
  std::string adapter;  // a file, or the name of a shipped adapter
  std::string suite = "ci";
  std::vector<std::string> scenes;
  std::string cache_dir = ".raygate";
  std::string golden_dir;  // default: the adapter's goldens (compare/golden.h)
  std::string baseline;    // raygate-baseline override
  std::string schedule = "alternate";
  std::vector<int> pin_cpus;
  bool no_pin = false;  // --no-pin: not even the default pinning of a round to one CPU
  std::size_t baseline_rounds = 0;  // rounds per scene the baseline joins; 0 = every round
  std::vector<int> duet_cpus{0, 1};
  int warmup = 1;
  StoppingPolicy stopping;  // --target, --min-rounds, ...; its defaults are the policy's own
  std::string metric;  // --timing: "" (the adapter's) or a mode's name (runner/timing/)
  int jobs = 0;
  std::string policy;  // gate policy file; "" = the defaults
  std::string shard;        // "K/N" (run and compare only); "" = every selected scene
  std::string shard_costs;  // results document whose scene times are the split's costs
};

void add_measure_options(CLI::App& command, MeasureArgs& args);

// --baseline-rounds: for compare and bisect, whose verdict needs no baseline (its default is
// the value in `args` when called).
void add_baseline_rounds_option(CLI::App& command, MeasureArgs& args);

// --shard K/N and --shard-costs: for run and compare, whose documents `raygate merge` joins.
void add_shard_options(CLI::App& command, MeasureArgs& args);

// Everything the options name, loaded and checked; UsageError for anything wrong.
MeasureContext load_measure_context(const MeasureArgs& args);

}  // namespace raygate::cli

// What a measuring command (run, compare, bisect) names, as the command line gives it: where the
// tracer is, how to build it, which scenes, the schedule, stopping and timing, the gate policy
// and the shard. load_measure_context() loads and checks all of it into a MeasureContext, so a
// front end only binds its options to these fields (cli/measure_options.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "measure/stopping_policy.h"
#include "pipeline/measure_context.h"

namespace raygate {

struct MeasureOptions {
  std::string repo = ".";
  std::string adapter;  // a file, or the name of a shipped adapter
  std::string suite = "ci";
  std::vector<std::string> scenes;
  std::string cache_dir = ".raygate";
  // Not given: the adapter's goldens (compare/golden.h); given empty: refused.
  std::optional<std::string> golden_dir;
  std::string baseline;  // raygate-baseline override
  std::string schedule = "alternate";
  std::vector<int> pin_cpus;
  bool no_pin = false;              // --no-pin: not even the default pinning of a round to one CPU
  bool no_idle_poll = false;        // --no-idle-poll: idle CPUs sleep as the kernel chooses
  std::size_t baseline_rounds = 0;  // rounds per scene the baseline joins; 0 = every round
  // Runs of each contender per round, the fastest kept; 0 (not given): one, and compare's second
  // pass repeats where it pays (MeasureContext::repeat_where_it_pays).
  std::size_t repeats = 0;
  std::vector<int> duet_cpus;  // --duet-cpus; none given: 0,1 (refused with --schedule alternate)
  int warmup = 1;
  StoppingPolicy stopping;  // --target, --min-rounds, ...; its defaults are the policy's own
  std::string metric;       // --timing: "" (the adapter's) or a mode's name (runner/timing/)
  int jobs = 0;
  std::string policy;       // gate policy file; "" = the defaults
  std::string shard;        // "K/N" (run and compare only); "" = every selected scene
  std::string shard_costs;  // results document whose scene times are the split's costs
};

// Everything the options name, loaded and checked; UsageError for anything wrong (InfraError
// when the timing mode's tool is missing). `warnings` gets what the user should hear before
// anything starts (a sim measurement's price), one line each.
MeasureContext load_measure_context(const MeasureOptions& options,
                                    std::vector<std::string>& warnings);

}  // namespace raygate

#include "cli/simulated_mode.h"

#include <fmt/core.h>

namespace raygate::cli {

void apply_simulated_mode(const MeasureArgs& args, MeasureContext& context) {
  if (args.metric == "sim") context.adapter.timing.source = TimingSource::simulated;
  if (!simulated(context)) return;
  context.metric.reset();
  context.cachegrind = find_cachegrind();
  // A warm-up warms nothing a simulation counts; two rounds show whether the counts repeat.
  context.schedule.warmup_runs = 0;
  // A count is the same on every CPU and the baseline's is cached after its first run, so sim
  // mode keeps the baseline in every round and needs no pinning: the two rounds that decide
  // are then the same round twice, every contender in each.
  context.schedule.normalizer_rounds = 0;
  context.schedule.round_cpus.clear();
  context.stopping.min_rounds = 2;
  context.stopping.max_rounds = std::max(context.stopping.max_rounds, std::size_t{2});
  if (args.policy.empty()) context.policy.defaults.max_slowdown = kSimulatedDefaultLimit;
  if (context.adapter.threads > 1) {
    fmt::print(stderr,
               "warning: {}: threads is {}, but valgrind runs a program's threads one at a time: "
               "the simulated cost counts all their work, not the parallel speed-up\n",
               context.adapter.file.string(), context.adapter.threads);
  }
}

}  // namespace raygate::cli

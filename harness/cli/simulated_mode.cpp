#include "cli/simulated_mode.h"

#include <fmt/core.h>

#include <memory>

namespace raygate::cli {

bool simulated(const MeasureContext& context) {
  return context.adapter.timing.source == TimingSource::simulated;
}

void apply_simulated_mode(const MeasureArgs& args, MeasureContext& context) {
  if (args.metric == "sim") context.adapter.timing.source = TimingSource::simulated;
  if (!simulated(context)) return;
  context.metric.reset();
  context.cachegrind = find_cachegrind();
  // A warm-up warms nothing a simulation counts; two rounds show whether the counts repeat.
  context.schedule.warmup_runs = 0;
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

BaselineContender make_baseline_contender(const MeasureContext& context,
                                          const std::string& baseline_source_sha256) {
  BaselineContender baseline(context.tools.baseline, context.suite.sampling,
                             std::chrono::minutes(30), "none", baseline_clock(context));
  if (simulated(context)) {
    baseline.simulate({*context.cachegrind,
                       std::make_shared<BaselineCostCache>(context.cache_dir / "simulated-baseline"),
                       baseline_source_sha256});
  }
  return baseline;
}

}  // namespace raygate::cli

#include "cli/simulated_mode.h"

#include <fmt/core.h>

#include <cmath>

namespace raygate::cli {
namespace {

// A rough price of the suite in sim mode, for a tracer as fast as the baseline: the ci suite's
// baseline pass is about 11 s natively for 13 scenes of 128x128 (docs/scenes.md), cachegrind
// about 31x slower (docs/simulated-timing.md "What it costs"), and a scene takes its tracers'
// two rounds plus the baseline's first (later ones are cached): 3 runs for a run, 5 for a compare.
double estimated_compare_seconds(const Suite& suite) {
  constexpr double kNativeSecondsPerPixel = 11.0 / (13.0 * 128.0 * 128.0);
  constexpr double kCachegrindSlowdown = 31.0;
  double pixels = 0.0;
  for (const SuiteScene& scene : suite.scenes) {
    pixels += scene.width > 0 && scene.height > 0 ? double(scene.width) * double(scene.height)
                                                  : 128.0 * 128.0;
  }
  return pixels * kNativeSecondsPerPixel * kCachegrindSlowdown * 5.0;
}

}  // namespace

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
  context.schedule.repeats = 1;  // a count does not vary: the fastest of two is the same count
  context.stopping.min_rounds = 2;
  context.stopping.max_rounds = std::max(context.stopping.max_rounds, std::size_t{2});
  if (args.policy.empty()) context.policy.defaults.max_slowdown = kSimulatedDefaultLimit;
  // Said before anything starts: a sim compare of the ci suite is a half-hour job.
  if (const double seconds = estimated_compare_seconds(context.suite); seconds > 10.0 * 60.0) {
    fmt::print(stderr,
               "warning: --timing sim runs every program under cachegrind, about 30x slower: "
               "suite {} ({} scenes) will take about {} min for a compare and {} min for a run "
               "of a tracer as fast as the baseline; the `sim` suite (the same scenes at 48x48) "
               "takes about {} min. Ctrl-C stops it, keeping the scenes done\n",
               context.suite.name, context.suite.scenes.size(), std::lround(seconds / 60.0),
               std::lround(seconds * 3.0 / 5.0 / 60.0),
               std::lround(seconds * 48.0 * 48.0 / (128.0 * 128.0) / 60.0));
  }
  if (context.adapter.threads > 1) {
    fmt::print(stderr,
               "warning: {}: threads is {}, but valgrind runs a program's threads one at a time: "
               "the simulated cost counts all their work, not the parallel speed-up\n",
               context.adapter.file.string(), context.adapter.threads);
  }
}

}  // namespace raygate::cli

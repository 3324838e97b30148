// `--timing sim` (docs/simulated-timing.md): every run under cachegrind, its cost the estimated
// cycles of the counted events (measure/simulated_cost.h), the same on every machine. What it
// changes in a measurement: no warm-ups (counting needs no warm caches), two rounds to check
// that the counts repeat, its own default limit, and warnings for a long suite and for
// multi-threaded tracers, which valgrind serializes.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "measure/stopping_policy.h"
#include "runner/timing/timing_mode.h"

namespace raygate {
namespace {

// The default max_slowdown without a policy file: a counted change needs no noise margin, but
// the model is an estimate of cycles, not cycles, so 1% rather than 0.
constexpr double kSimulatedDefaultLimit = 0.01;

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

class Simulated final : public TimingMode {
 public:
  std::string_view name() const override { return "sim"; }
  std::string_view description() const override {
    return "simulated cycles under valgrind's cachegrind (docs/simulated-timing.md)";
  }
  std::string_view tracer_clock() const override { return "simulated-cycles"; }
  std::string_view baseline_clock() const override { return "simulated-cycles"; }
  TimingSource source() const override { return TimingSource::simulated; }
  bool exact() const override { return true; }
  bool under_cachegrind() const override { return true; }
  std::string_view unit() const override { return "cycles"; }

  std::optional<double> seconds(const RunRecord& run) const override {
    if (!run.simulated) return std::nullopt;
    return estimated_cycles(*run.simulated);
  }

  ProcessSpec wrap(ProcessSpec spec, const std::filesystem::path& run_dir,
                   const std::optional<Cachegrind>& simulator) const override {
    if (!simulator) throw std::logic_error("simulated timing without cachegrind");
    return raygate::under_cachegrind(std::move(spec), *simulator, cachegrind_dir(run_dir));
  }

  void collect(RunRecord& run, const std::filesystem::path& run_dir) const override {
    record_simulated_cost(run, cachegrind_dir(run_dir));
    // The peak metered is valgrind's, the tracer's memory inside its own several times over:
    // kept as a record, not as the tracer's peak the memory gate judges and reports print.
    run.max_rss_own = false;
  }

  void prepare(TimingPlan& plan) const override {
    plan.cachegrind = find_cachegrind();
    // A warm-up warms nothing a simulation counts; two rounds show whether the counts repeat.
    plan.schedule.warmup_runs = 0;
    // A count is the same on every CPU and the baseline's is cached after its first run, so
    // sim mode keeps the baseline in every round and needs no pinning: the two rounds that
    // decide are then the same round twice, every contender in each.
    plan.schedule.normalizer_rounds = 0;
    plan.schedule.round_cpus.clear();
    plan.schedule.repeats = 1;  // a count does not vary: the fastest of two is the same count
    plan.stopping.min_rounds = 2;
    plan.stopping.max_rounds = std::max(plan.stopping.max_rounds, std::size_t{2});
    plan.default_max_slowdown = kSimulatedDefaultLimit;
    warn_of_cost(plan);
  }

 private:
  static void warn_of_cost(TimingPlan& plan) {
    // Said before anything starts: a sim compare of the ci suite is a half-hour job.
    if (const double seconds = estimated_compare_seconds(plan.suite); seconds > 10.0 * 60.0) {
      plan.warnings.push_back(fmt::format(
          "--timing sim runs every program under cachegrind, about 30x slower: suite {} ({} "
          "scenes) will take about {} min for a compare and {} min for a run of a tracer as "
          "fast as the baseline; the `sim` suite (the same scenes at 48x48) takes about {} "
          "min. Ctrl-C stops it, keeping the scenes done",
          plan.suite.name, plan.suite.scenes.size(), std::lround(seconds / 60.0),
          std::lround(seconds * 3.0 / 5.0 / 60.0),
          std::lround(seconds * 48.0 * 48.0 / (128.0 * 128.0) / 60.0)));
    }
    if (plan.threads > 1) {
      plan.warnings.push_back(
          fmt::format("{}: threads is {}, but valgrind runs a program's threads one at a time: the "
                      "simulated cost counts all their work, not the parallel speed-up",
                      plan.adapter_file.string(), plan.threads));
    }
  }
};

}  // namespace

std::unique_ptr<TimingMode> make_simulated_mode() { return std::make_unique<Simulated>(); }

}  // namespace raygate

// Command-line options shared by the commands that measure (run, compare, bisect): where the
// tracer is, how to build it, which scenes, and the schedule and stopping policy. One place, so
// every measuring command spells its flags the same way.
#pragma once

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "adapter/adapter.h"
#include "core/paths.h"
#include "gate/policy.h"
#include "measure/stopping.h"
#include "runner/baseline_contender.h"
#include "runner/cachegrind.h"
#include "runner/scheduler.h"
#include "runner/suite.h"
#include "store/shard.h"

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
  std::vector<int> duet_cpus{0, 1};
  int warmup = 1;
  double target = 0.01;
  std::size_t min_rounds = 3;
  std::size_t max_rounds = 30;
  double max_seconds = 300;
  std::string metric;  // "" (the adapter's), wall, cpu, sim
  int jobs = 0;
  std::string policy;  // gate policy file; "" = the defaults
  std::string shard;        // "K/N" (run and compare only); "" = every selected scene
  std::string shard_costs;  // results document whose scene times are the split's costs
};

void add_measure_options(CLI::App& command, MeasureArgs& args);

// --shard K/N and --shard-costs: for run and compare, whose documents `raygate merge` joins.
void add_shard_options(CLI::App& command, MeasureArgs& args);

// Everything the options name, loaded and checked; UsageError for anything wrong.
struct MeasureContext {
  ToolPaths tools;
  Adapter adapter;
  Suite suite;
  std::vector<SuiteScene> scenes;
  std::optional<ShardRecord> shard;  // --shard: `scenes` is this shard of the selection
  std::filesystem::path cache_dir;
  std::filesystem::path golden_dir;
  ScheduleOptions schedule;
  StoppingPolicy stopping;
  std::optional<TimingMetric> metric;
  GatePolicy policy;
  int jobs = 0;  // parallel build jobs; 0 = every allowed CPU
  bool quiet = false;  // --quiet: builds and measurements say nothing on standard error
  std::optional<Cachegrind> cachegrind;  // sim mode (cli/simulated_mode.h)
};

MeasureContext load_measure_context(const MeasureArgs& args);

// How the tracer is timed in this measurement: the adapter's timing, --timing overriding its
// process metric.
TimingMetric tracer_metric(const MeasureContext& context);

// How the baseline is timed: by the tracer's clock (process wall or CPU), or by its in-process
// seconds when the tracer reports its own time (DESIGN.md §11).
BaselineClock baseline_clock(const MeasureContext& context);

// ", shard K/N of M selected scenes" with --shard, else "": for the line that opens a run.
std::string shard_note(const MeasureContext& context);

// The settings object of a results document: how this measurement was made.
nlohmann::json measure_settings(const MeasureContext& context);

}  // namespace raygate::cli

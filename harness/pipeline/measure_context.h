// Everything a measurement needs, loaded and checked: the tools, the adapter, the suite and its
// selected scenes (or one shard of them), the schedule, the stopping policy and the gate policy.
// The command line builds it from options (cli/measure_options.h); the pipeline reads it.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "adapter/adapter.h"
#include "core/paths.h"
#include "gate/policy.h"
#include "measure/stopping_policy.h"
#include "pipeline/output_failures.h"
#include "results/measurement_settings.h"
#include "results/shard.h"
#include "runner/baseline_contender.h"
#include "runner/cachegrind.h"
#include "runner/idle_poll.h"
#include "runner/scheduler.h"
#include "runner/suite.h"
#include "runner/timing/timing_mode.h"

namespace raygate {

struct MeasureContext {
  ToolPaths tools;
  Adapter adapter;
  Suite suite;
  std::vector<SuiteScene> scenes;
  std::optional<ShardRecord> shard;  // --shard: `scenes` is this shard of the selection
  std::filesystem::path cache_dir;
  std::filesystem::path golden_dir;
  ScheduleOptions schedule;
  // --repeats not given: one run per round, and from a scene's 11th round on, where its rounds
  // show that each side's fastest of two gets there sooner, it takes it (compare: pipeline/
  // visit_plan.h, in both passes; run: pipeline/ratio_repeats.h).
  bool repeat_where_it_pays = false;
  // Idle CPUs are held polling while measuring through this PM QoS file (runner/idle_poll.h);
  // empty: left to the kernel (--no-idle-poll). Never in sim mode, whose counts no idle state
  // moves.
  std::filesystem::path idle_poll_device{kCpuLatencyDevice};
  StoppingPolicy stopping;
  // How runs are timed (runner/timing/): --timing's word ("" = the adapter's own) and the mode
  // it resolved to (choose_timing); null: the adapter's.
  std::string timing_choice;
  const TimingMode* timing = nullptr;
  GatePolicy policy;
  int jobs = 0;                          // parallel build jobs; 0 = every allowed CPU
  std::optional<Cachegrind> cachegrind;  // sim mode (docs/simulated-timing.md)
  // compare --explain: profile each REGRESSED scene's base and head once under cachegrind
  // (pipeline/explain_stage.h); sim mode explains from its own runs without it.
  bool explain = false;
  // The files the options named that the measurement reads (adapter, suite, policy, shard
  // costs): an output must not be one of them (check_publish_targets, calibrate's -o).
  std::vector<NamedFile> input_files;
};

// The measurement's timing mode: the one choose_timing set, or the adapter's. Both sides of the
// ratio are timed by it (DESIGN.md §11).
const TimingMode& timing_mode(const MeasureContext& context);

// The mode's two questions (timing_mode.h): does every run repeat its reading exactly (a change
// can be exact; no warm-ups, no held idle CPUs), and do runs execute under cachegrind (its
// files explain a regression; the baseline's counts are cached)? --timing sim answers yes to
// both; a hardware instruction counter would be exact without cachegrind.
bool exact_timing(const MeasureContext& context);
bool under_cachegrind(const MeasureContext& context);

// Resolves --timing's `choice` ("" = the adapter's) against the adapter and lets the mode adjust
// the measurement (timing_mode.h, prepare): schedule, stopping budget, the simulator, and the
// gate's default limit unless `policy_given`. Returns the warnings the mode has for the user.
// UsageError for an unknown choice; InfraError when the mode's tool is missing.
std::vector<std::string> choose_timing(MeasureContext& context, const std::string& choice,
                                       bool policy_given);

// ", shard K/N of M selected scenes" with --shard, else "": for the line that opens a run.
std::string shard_note(const MeasureContext& context);

// The CPUs the tracer's runs are pinned to because its adapter asks (pin_cpus: true) and no
// --pin names others: the first `threads` CPUs this process may use; empty otherwise.
std::vector<int> adapter_pinned_cpus(const MeasureContext& context);

// The settings of a results document: how this measurement was made (everything but whose
// goldens judged it, which the golden manifest says: pipeline/suite_measurement.cpp).
MeasurementSettings measure_settings(const MeasureContext& context);

}  // namespace raygate

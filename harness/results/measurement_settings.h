// How a results document's measurement was made (its `settings` member): schedule, stopping
// budget, clocks, goldens, the gate limits it was measured under, the shard. A typed record,
// read and written only at the JSON boundary (results/settings_json.cpp), so the gate, the
// reports, the store and merge ask fields rather than look up words.
//
// Every field is optional because documents say only what their raygate knew: one written
// before the clocks were matched has no tracer_clock, a test's has only a schedule. An absent
// field is written back absent, so a document reads and writes to the same JSON (the store's
// duplicate check compares it); readers fall back to the default that applied when it was
// missing. Keys this raygate does not know (from a newer one) are kept as they were read.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "adapter/adapter.h"
#include "results/shard_record.h"
#include "runner/scheduler.h"

namespace raygate {

// Who chose the CPUs the tracer was pinned to (settings.pinned_by).
enum class PinnedBy { none, adapter, option };  // "", "adapter", "--pin"

// Idle CPUs while measuring (settings.cpu_idle; runner/idle_poll.h): as the kernel chose, or
// held polling.
enum class CpuIdle { os, poll };  // "os", "poll"

// One shard a merged document was made of (settings.merged_shards[]).
struct MergedShard {
  ShardSpec spec;
  std::string document;  // where merge read it
  std::string raygate_version;
  std::string started_at;
  std::string finished_at;
  bool complete = false;
  std::vector<std::string> scenes;  // ids it measured
  nlohmann::json machine;           // its MachineContext, as ResultsDocument::machine

  bool operator==(const MergedShard&) const = default;
};

struct MeasurementSettings {
  // The schedule of rounds (runner/scheduler.h ScheduleOptions).
  std::optional<ScheduleKind> schedule;
  std::optional<int> warmup_runs;
  std::optional<std::vector<int>> pin_cpus;  // what was really pinned (issue 26)
  std::optional<PinnedBy> pinned_by;
  std::optional<std::vector<int>> duet_cpus;
  std::optional<std::vector<int>> round_cpus;
  std::optional<std::size_t> baseline_rounds;  // ScheduleOptions::normalizer_rounds
  std::optional<std::size_t> repeats;
  // Idle CPUs while measuring, and why polling was not held when it was asked for ("cannot open
  // /dev/cpu_dma_latency: Permission denied"): absent in documents from before it.
  std::optional<CpuIdle> cpu_idle;
  std::optional<std::string> cpu_idle_refused;
  // The stopping budget (measure/stopping_policy.h).
  std::optional<double> target_relative_half_width;
  std::optional<std::size_t> min_rounds;
  std::optional<std::size_t> max_rounds;
  std::optional<double> max_seconds_per_scene;
  std::optional<double> max_minutes;
  // The clocks (runner/timing/): names from the timing modes' open set, so strings.
  std::optional<std::string> metric;  // --timing's word, the adapter's metric, or a counted clock
  std::optional<bool> metric_by_threads;  // the adapter's "auto" chose the metric
  std::optional<TimingSource> timing_source;
  std::optional<std::string> tracer_clock;  // absent before the clocks were matched (issue 18)
  std::optional<std::string> baseline_clock;
  // The unit of every run's measure and of the medians (the timing mode's): "seconds",
  // "cycles". Absent before 2026-11-28; measure_unit() then infers it.
  std::optional<std::string> unit;
  std::optional<int> threads;
  // Goldens: the folder, and whose they are ("none": the tracer has none yet).
  std::optional<std::string> golden_dir;
  std::optional<std::string> goldens;
  // How the tracer's images were judged: chosen once, from the adapter, when measuring began;
  // absent in documents from before it (readers then fall back to deterministic, or to the
  // adapter file when it is still there and unchanged).
  std::optional<ImageKind> images;
  std::optional<double> image_tolerance;  // the Monte Carlo images' (gate/policy.h)
  // The gate's policy as measured: its file and its default limits.
  std::optional<std::string> policy_file;
  std::optional<double> max_slowdown;
  std::optional<double> significance;
  std::optional<double> family_significance;
  std::optional<double> max_exponent_increase;
  std::optional<double> max_memory_increase;
  // A shard of a CI matrix (--shard K/N), or the shards a merged document was made of.
  std::optional<ShardRecord> shard;
  std::optional<std::vector<MergedShard>> merged_shards;
  // Keys this raygate does not know, as read: an object, or null when there are none.
  nlohmann::json unknown;

  // The timing was simulated (--timing sim), so a measure is cycles, not seconds.
  bool simulated() const;
  // The unit of a run's measure: `unit`, or in older documents cycles when simulated, else
  // seconds.
  std::string measure_unit() const;

  bool operator==(const MeasurementSettings&) const = default;
};

}  // namespace raygate

#include "pipeline/measure_context.h"

#include <fmt/core.h>

#include <algorithm>

#include "core/process.h"
#include "runner/timing/timing_modes.h"

namespace raygate {

const TimingMode& timing_mode(const MeasureContext& context) {
  return context.timing != nullptr ? *context.timing : adapter_timing_mode(context.adapter.timing);
}

bool exact_timing(const MeasureContext& context) { return timing_mode(context).exact(); }

bool under_cachegrind(const MeasureContext& context) {
  return timing_mode(context).under_cachegrind();
}

std::vector<std::string> choose_timing(MeasureContext& c, const std::string& choice,
                                       bool policy_given) {
  const TimingMode& mode = resolve_timing_mode(c.adapter.timing, choice);
  c.timing = &mode;
  c.timing_choice = choice;
  // The source actually used, as the adapter's: the measurement hash (builder/build_cache.h)
  // and the document's timing_source name it.
  c.adapter.timing.source = mode.source();
  TimingPlan plan{c.suite, c.adapter.threads, c.adapter.file, c.schedule, c.stopping, {}, {}, {}};
  mode.prepare(plan);
  c.cachegrind = std::move(plan.cachegrind);
  if (plan.default_max_slowdown && !policy_given) {
    c.policy.defaults.max_slowdown = *plan.default_max_slowdown;
  }
  return std::move(plan.warnings);
}

namespace {

// settings.metric: the clock's word (--timing's, else the adapter's metric), or an exact mode's
// clock name, as documents have always said.
std::string settings_metric(const MeasureContext& c) {
  const TimingMode& mode = timing_mode(c);
  if (mode.exact()) return std::string(mode.tracer_clock());
  if (!c.timing_choice.empty()) return c.timing_choice;
  return std::string(to_string(c.adapter.timing.metric));
}

}  // namespace

std::string shard_note(const MeasureContext& context) {
  if (!context.shard) return {};
  return fmt::format(", shard {} of {} selected scenes", to_string(context.shard->spec),
                     context.shard->suite_scenes.size());
}

std::vector<int> adapter_pinned_cpus(const MeasureContext& context) {
  if (!context.adapter.pin_cpus || !context.schedule.pin_cpus.empty()) return {};
  const std::vector<int> allowed = allowed_cpu_list();
  const std::size_t count =
      std::min(allowed.size(), static_cast<std::size_t>(std::max(context.adapter.threads, 1)));
  return {allowed.begin(), allowed.begin() + static_cast<long>(count)};
}

namespace {

// Who chose the pinned CPUs: the adapter's pin_cpus, --pin, or nobody.
PinnedBy pinned_by(const MeasureContext& c, const std::vector<int>& adapter_cpus) {
  if (!adapter_cpus.empty()) return PinnedBy::adapter;
  return c.schedule.pin_cpus.empty() ? PinnedBy::none : PinnedBy::option;
}

}  // namespace

MeasurementSettings measure_settings(const MeasureContext& c) {
  // What was really pinned: --pin's CPUs, or those the adapter's pin_cpus chose (issue 26: a
  // document said "pin_cpus": [] while the adapter had pinned the tracer to CPU 0).
  const std::vector<int> adapter_cpus = adapter_pinned_cpus(c);
  const TimingMode& mode = timing_mode(c);
  // One literal in the record's order; the policy's limits are those it will be judged again
  // by (gate/policy.h recorded_policy).
  return {.schedule = c.schedule.kind,
          .warmup_runs = c.schedule.warmup_runs,
          .pin_cpus = adapter_cpus.empty() ? c.schedule.pin_cpus : adapter_cpus,
          .pinned_by = pinned_by(c, adapter_cpus),
          .duet_cpus = c.schedule.duet_cpus,
          .round_cpus = c.schedule.round_cpus,
          .baseline_rounds = c.schedule.normalizer_rounds,
          .repeats = c.schedule.repeats,
          // As asked; measure_suite says "os" instead when the machine refuses the hold.
          .cpu_idle = exact_timing(c)
                          ? std::nullopt
                          : std::optional(c.idle_poll_device.empty() ? CpuIdle::os : CpuIdle::poll),
          .cpu_idle_refused = std::nullopt,
          .target_relative_half_width = c.stopping.target_relative_half_width,
          .min_rounds = c.stopping.min_rounds,
          .max_rounds = c.stopping.max_rounds,
          .max_seconds_per_scene = c.stopping.max_seconds,
          .max_minutes = c.stopping.max_minutes,
          .metric = settings_metric(c),
          .metric_by_threads =
              !exact_timing(c) && c.timing_choice.empty() && c.adapter.timing.metric_by_threads,
          .timing_source = mode.source(),
          .tracer_clock = std::string(mode.tracer_clock()),
          .baseline_clock = std::string(mode.baseline_clock()),
          .unit = std::string(mode.unit()),
          .threads = c.adapter.threads,
          .golden_dir = c.golden_dir.string(),
          .goldens = std::nullopt,  // whose they are: new_document reads the golden manifest
          .images = c.adapter.images,
          .image_tolerance = c.policy.defaults.image_tolerance,
          .policy_file = c.policy.file.string(),
          .max_slowdown = c.policy.defaults.max_slowdown,
          .significance = c.policy.defaults.significance,
          .family_significance = c.policy.family_significance,
          .max_exponent_increase = c.policy.max_exponent_increase,
          .max_memory_increase = c.policy.defaults.max_memory_increase,
          .shard = c.shard,
          .merged_shards = std::nullopt,
          .unknown = {}};
}

}  // namespace raygate

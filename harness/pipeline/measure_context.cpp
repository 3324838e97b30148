#include "pipeline/measure_context.h"

#include <fmt/core.h>

#include <algorithm>

#include "core/process.h"

namespace raygate {

bool simulated(const MeasureContext& context) {
  return context.adapter.timing.source == TimingSource::simulated;
}

TimingMetric tracer_metric(const MeasureContext& context) {
  return context.metric.value_or(context.adapter.timing.metric);
}

BaselineClock baseline_clock(const MeasureContext& context) {
  return matching_baseline_clock(context.adapter.timing.source, tracer_metric(context));
}

std::string shard_note(const MeasureContext& context) {
  if (!context.shard) return {};
  return fmt::format(", shard {} of {} selected scenes", to_string(context.shard->spec),
                     context.shard->suite_scenes.size());
}

std::vector<int> adapter_pinned_cpus(const MeasureContext& context) {
  if (!context.adapter.pin_cpus || !context.schedule.pin_cpus.empty()) return {};
  const std::vector<int> allowed = allowed_cpu_list();
  const std::size_t count = std::min(
      allowed.size(), static_cast<std::size_t>(std::max(context.adapter.threads, 1)));
  return {allowed.begin(), allowed.begin() + static_cast<long>(count)};
}

nlohmann::json measure_settings(const MeasureContext& c) {
  // What was really pinned: --pin's CPUs, or those the adapter's pin_cpus chose (issue 26: a
  // document said "pin_cpus": [] while the adapter had pinned the tracer to CPU 0).
  const std::vector<int> adapter_cpus = adapter_pinned_cpus(c);
  nlohmann::json settings = {
      {"schedule", std::string(to_string(c.schedule.kind))},
      {"warmup_runs", c.schedule.warmup_runs},
      {"pin_cpus", adapter_cpus.empty() ? c.schedule.pin_cpus : adapter_cpus},
      {"pinned_by", !adapter_cpus.empty()            ? "adapter"
                    : !c.schedule.pin_cpus.empty()   ? "--pin"
                                                     : ""},
      {"duet_cpus", c.schedule.duet_cpus},
      {"round_cpus", c.schedule.round_cpus},
      {"baseline_rounds", c.schedule.normalizer_rounds},
      {"repeats", c.schedule.repeats},
      {"target_relative_half_width", c.stopping.target_relative_half_width},
      {"min_rounds", c.stopping.min_rounds},
      {"max_rounds", c.stopping.max_rounds},
      {"max_seconds_per_scene", c.stopping.max_seconds},
      {"max_minutes", c.stopping.max_minutes},
      {"metric", simulated(c)  ? std::string(tracer_clock_name(c.adapter.timing.source, {}))
                 : c.metric ? std::string(to_string(*c.metric))
                            : std::string(to_string(c.adapter.timing.metric))},
      {"metric_by_threads", !simulated(c) && !c.metric && c.adapter.timing.metric_by_threads},
      {"timing_source", std::string(to_string(c.adapter.timing.source))},
      {"tracer_clock",
       std::string(tracer_clock_name(c.adapter.timing.source, tracer_metric(c)))},
      {"baseline_clock", std::string(to_string(baseline_clock(c)))},
      {"threads", c.adapter.threads},
      {"golden_dir", c.golden_dir.string()},
      {"policy_file", c.policy.file.string()},
      {"max_slowdown", c.policy.defaults.max_slowdown},
      {"significance", c.policy.defaults.significance},
      {"family_significance", c.policy.family_significance},
      {"max_exponent_increase", c.policy.max_exponent_increase},
      {"max_memory_increase", c.policy.defaults.max_memory_increase}};
  if (c.shard) settings["shard"] = shard_to_json(*c.shard);
  return settings;
}

}  // namespace raygate

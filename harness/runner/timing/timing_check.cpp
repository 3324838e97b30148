#include "runner/timing/timing_check.h"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

#include "runner/timing/timing_modes.h"

namespace raygate {
namespace {

// A counter's value: a run's measure may be estimated cycles (1e18 is past any of them), and a
// counter is no larger than the measures it is taken beside.
constexpr double kMaxCounter = 1e18;

// The clock names of documents written before the clocks were matched (docs/results-format.md):
// no mode carries them any more, but their documents must stay readable.
constexpr std::string_view kRetiredClocks[] = {"in-process-cpu"};

void add_once(std::vector<std::string>& names, std::string_view name) {
  if (std::find(names.begin(), names.end(), name) == names.end()) names.emplace_back(name);
}

void require_known(const JsonField& field, const std::string& word,
                   const std::vector<std::string>& known) {
  if (std::find(known.begin(), known.end(), word) != known.end()) return;
  field.fail(fmt::format("unknown value \"{}\" (one of: {})", word, fmt::join(known, ", ")));
}

std::vector<std::string> known_units(const TimingModeList& modes) {
  std::vector<std::string> units;
  for (const TimingMode* mode : modes) add_once(units, mode->unit());
  return units;
}

std::optional<CounterSpec> find_counter(const TimingModeList& modes, std::string_view name) {
  for (const TimingMode* mode : modes) {
    for (const CounterSpec& spec : mode->counters()) {
      if (spec.name == name) return spec;
    }
  }
  return std::nullopt;
}

std::vector<std::string> counter_names(const TimingModeList& modes) {
  std::vector<std::string> names;
  for (const TimingMode* mode : modes) {
    for (const CounterSpec& spec : mode->counters()) add_once(names, spec.name);
  }
  return names;
}

void check_counter(const JsonField& counter, const CounterSpec& spec) {
  if (!counter.value().is_object()) counter.fail("expected an object with value and unit");
  const JsonField unit = counter.member("unit");
  if (unit.as_string() != spec.unit) {
    unit.fail(fmt::format("\"{}\" is not the unit of {} (\"{}\")", unit.as_string(), spec.name,
                          spec.unit));
  }
  const JsonField value = counter.member("value");
  const double v = value.as_number();
  if (!std::isfinite(v) || v < 0.0 || v > kMaxCounter) {
    value.fail(fmt::format("{} is out of range (from 0 to {})", value.value().dump(), kMaxCounter));
  }
}

}  // namespace

std::vector<std::string> known_clock_names(const TimingModeList& modes) {
  std::vector<std::string> names;
  for (const TimingMode* mode : modes) {
    add_once(names, mode->tracer_clock());
    add_once(names, mode->baseline_clock());
  }
  for (const std::string_view retired : kRetiredClocks) add_once(names, retired);
  return names;
}

void check_clock_name(const JsonField& field, const TimingModeList& modes) {
  require_known(field, field.as_string(), known_clock_names(modes));
}

namespace {

void check_settings_timing(const JsonField& settings, const TimingModeList& modes) {
  for (const char* key : {"tracer_clock", "baseline_clock"}) {
    if (settings.has(key)) check_clock_name(settings.member(key), modes);
  }
  if (settings.has("unit")) {
    const JsonField unit = settings.member("unit");
    require_known(unit, unit.as_string(), known_units(modes));
  }
  // What --timing named (a mode), an exact mode's clock, or the adapter's wall or cpu.
  if (settings.has("metric")) {
    std::vector<std::string> metrics = known_clock_names(modes);
    for (const TimingMode* mode : modes) add_once(metrics, mode->name());
    for (const char* adapter_metric : {"wall", "cpu"}) add_once(metrics, adapter_metric);
    const JsonField metric = settings.member("metric");
    require_known(metric, metric.as_string(), metrics);
  }
}

}  // namespace

void check_run_counters(const JsonField& counters, const TimingModeList& modes) {
  if (!counters.value().is_object()) counters.fail("expected an object of counters by name");
  for (const std::string& name : counters.keys()) {
    const std::optional<CounterSpec> spec = find_counter(modes, name);
    if (!spec) {
      counters.member(name).fail(fmt::format("unknown counter \"{}\" (known: {})", name,
                                             fmt::join(counter_names(modes), ", ")));
    }
    check_counter(counters.member(name), *spec);
  }
}

namespace {

void check_run(const JsonField& run, const TimingModeList& modes) {
  if (run.value().is_object() && run.has("counters")) {
    check_run_counters(run.member("counters"), modes);
  }
}

void check_runs_by_role(const JsonField& runs, const TimingModeList& modes) {
  for (const std::string& role : runs.keys()) check_run(runs.member(role), modes);
}

// Where a scene keeps runs (results/results_json.cpp): its shape is checked already.
void check_scene_runs(const JsonField& scene, const TimingModeList& modes) {
  if (scene.has("failure") && !scene.member("failure").value().is_null()) {
    check_run(scene.member("failure").member("run"), modes);
  }
  const JsonField warmup = scene.member("warmup");
  for (const std::string& role : warmup.keys()) {
    for (const JsonField& run : warmup.member(role).elements()) check_run(run, modes);
  }
  for (const JsonField& round : scene.member("rounds").elements()) {
    check_runs_by_role(round.member("runs"), modes);
  }
  if (scene.has("partial_round")) check_runs_by_role(scene.member("partial_round"), modes);
}

}  // namespace

void check_document_timing(const JsonField& document, const TimingModeList& modes) {
  check_clock_name(document.member("baseline").member("timing"), modes);
  if (const JsonField settings = document.member("settings"); settings.value().is_object()) {
    check_settings_timing(settings, modes);
  }
  for (const JsonField& scene : document.member("scenes").elements()) {
    check_scene_runs(scene, modes);
  }
}

}  // namespace raygate

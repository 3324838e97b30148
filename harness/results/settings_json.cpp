// Field by field: a known key is read into its typed field and checked there; any other key is
// kept as it came, so a newer raygate's settings survive a read and write by this one.
#include "results/settings_json.h"

#include <algorithm>
#include <array>
#include <string_view>

#include "results/typed_fields.h"

namespace raygate {
namespace {

using json = nlohmann::json;
using namespace typed_fields;

// Every key MeasurementSettings has a field for; the rest go to `unknown`.
constexpr auto kKnownKeys = std::to_array<std::string_view>(
    {"schedule", "warmup_runs", "pin_cpus", "pinned_by", "duet_cpus", "round_cpus",
     "baseline_rounds", "repeats", "target_relative_half_width", "min_rounds", "max_rounds",
     "max_seconds_per_scene", "max_minutes", "metric", "metric_by_threads", "timing_source",
     "tracer_clock", "baseline_clock", "threads", "golden_dir", "goldens", "policy_file",
     "max_slowdown", "significance", "family_significance", "max_exponent_increase",
     "max_memory_increase", "shard", "merged_shards"});

bool known_key(std::string_view key) {
  return std::find(kKnownKeys.begin(), kKnownKeys.end(), key) != kKnownKeys.end();
}

// An enum read by its word: the words are the enum's own to_string, so one table spells them.
template <typename Enum, std::size_t N>
Enum word_from(const JsonField& field, const std::array<Enum, N>& values, const char* what) {
  const std::string word = field.as_string();
  std::string known;
  for (const Enum value : values) {
    if (to_string(value) == word) return value;
    known += (known.empty() ? "\"" : ", \"") + std::string(to_string(value)) + "\"";
  }
  field.fail("unknown " + std::string(what) + " \"" + word + "\" (" + known + ")");
}

constexpr std::array<ScheduleKind, 2> kSchedules{ScheduleKind::alternate, ScheduleKind::duet};
constexpr std::array<TimingSource, 3> kSources{TimingSource::process, TimingSource::reported,
                                               TimingSource::simulated};
constexpr std::array<PinnedBy, 3> kPinners{PinnedBy::none, PinnedBy::adapter, PinnedBy::option};

json shard_json(const ShardRecord& record) {
  return {{"index", record.spec.index},
          {"count", record.spec.count},
          {"suite_scenes", record.suite_scenes},
          {"cost_basis", record.cost_basis}};
}

ShardRecord shard_from(const JsonField& j) {
  ShardRecord record;
  record.spec.index = int_of(j.member("index"));
  record.spec.count = int_of(j.member("count"));
  if (j.has("suite_scenes")) record.suite_scenes = string_list(j.member("suite_scenes"));
  if (j.has("cost_basis")) record.cost_basis = j.member("cost_basis").as_string();
  if (record.spec.count < 1 || record.spec.index < 1 || record.spec.index > record.spec.count) {
    j.fail("index " + std::to_string(record.spec.index) + " of count " +
           std::to_string(record.spec.count) + " is not a shard (1 <= index <= count)");
  }
  return record;
}

json merged_json(const MergedShard& m) {
  return {{"index", m.spec.index},       {"count", m.spec.count},
          {"document", m.document},      {"raygate_version", m.raygate_version},
          {"started_at", m.started_at},  {"finished_at", m.finished_at},
          {"complete", m.complete},      {"scenes", m.scenes},
          {"machine", m.machine}};
}

MergedShard merged_from(const JsonField& j) {
  MergedShard m;
  m.spec = {int_of(j.member("index")), int_of(j.member("count"))};
  m.document = j.member("document").as_string();
  m.raygate_version = j.member("raygate_version").as_string();
  m.started_at = j.member("started_at").as_string();
  m.finished_at = j.member("finished_at").as_string();
  m.complete = j.member("complete").as_bool();
  m.scenes = string_list(j.member("scenes"));
  m.machine = j.member("machine").value();
  return m;
}

template <typename T, typename Write>
void put(json& j, const char* key, const std::optional<T>& value, Write write) {
  if (value) j[key] = write(*value);
}

template <typename T, typename Read>
void take(const JsonField& settings, const char* key, std::optional<T>& out, Read read) {
  if (settings.has(key)) out = read(settings.member(key));
}

const auto as_is = [](const auto& value) { return json(value); };
const auto as_word = [](auto value) { return json(std::string(to_string(value))); };
const auto a_string = [](const JsonField& f) { return f.as_string(); };
const auto a_flag = [](const JsonField& f) { return f.as_bool(); };
const auto a_number = [](const JsonField& f) { return number_or_nan(f); };
const auto an_int = [](const JsonField& f) { return int_of(f); };
const auto a_count = [](const JsonField& f) { return count_of(f); };
const auto cpus = [](const JsonField& f) { return int_list(f); };

void put_schedule(json& j, const MeasurementSettings& s) {
  put(j, "schedule", s.schedule, as_word);
  put(j, "warmup_runs", s.warmup_runs, as_is);
  put(j, "pin_cpus", s.pin_cpus, as_is);
  put(j, "pinned_by", s.pinned_by, as_word);
  put(j, "duet_cpus", s.duet_cpus, as_is);
  put(j, "round_cpus", s.round_cpus, as_is);
  put(j, "baseline_rounds", s.baseline_rounds, as_is);
  put(j, "repeats", s.repeats, as_is);
  put(j, "target_relative_half_width", s.target_relative_half_width, as_is);
  put(j, "min_rounds", s.min_rounds, as_is);
  put(j, "max_rounds", s.max_rounds, as_is);
  put(j, "max_seconds_per_scene", s.max_seconds_per_scene, as_is);
  put(j, "max_minutes", s.max_minutes, as_is);
}

void take_schedule(const JsonField& f, MeasurementSettings& s) {
  take(f, "schedule", s.schedule,
       [](const JsonField& w) { return word_from(w, kSchedules, "schedule"); });
  take(f, "warmup_runs", s.warmup_runs, an_int);
  take(f, "pin_cpus", s.pin_cpus, cpus);
  take(f, "pinned_by", s.pinned_by,
       [](const JsonField& w) { return word_from(w, kPinners, "pinner"); });
  take(f, "duet_cpus", s.duet_cpus, cpus);
  take(f, "round_cpus", s.round_cpus, cpus);
  take(f, "baseline_rounds", s.baseline_rounds, a_count);
  take(f, "repeats", s.repeats, a_count);
  take(f, "target_relative_half_width", s.target_relative_half_width, a_number);
  take(f, "min_rounds", s.min_rounds, a_count);
  take(f, "max_rounds", s.max_rounds, a_count);
  take(f, "max_seconds_per_scene", s.max_seconds_per_scene, a_number);
  take(f, "max_minutes", s.max_minutes, a_number);
}

void put_clocks_and_policy(json& j, const MeasurementSettings& s) {
  put(j, "metric", s.metric, as_is);
  put(j, "metric_by_threads", s.metric_by_threads, as_is);
  put(j, "timing_source", s.timing_source, as_word);
  put(j, "tracer_clock", s.tracer_clock, as_is);
  put(j, "baseline_clock", s.baseline_clock, as_is);
  put(j, "threads", s.threads, as_is);
  put(j, "golden_dir", s.golden_dir, as_is);
  put(j, "goldens", s.goldens, as_is);
  put(j, "policy_file", s.policy_file, as_is);
  put(j, "max_slowdown", s.max_slowdown, as_is);
  put(j, "significance", s.significance, as_is);
  put(j, "family_significance", s.family_significance, as_is);
  put(j, "max_exponent_increase", s.max_exponent_increase, as_is);
  put(j, "max_memory_increase", s.max_memory_increase, as_is);
}

void take_clocks_and_policy(const JsonField& f, MeasurementSettings& s) {
  take(f, "metric", s.metric, a_string);
  take(f, "metric_by_threads", s.metric_by_threads, a_flag);
  take(f, "timing_source", s.timing_source,
       [](const JsonField& w) { return word_from(w, kSources, "timing source"); });
  take(f, "tracer_clock", s.tracer_clock, a_string);
  take(f, "baseline_clock", s.baseline_clock, a_string);
  take(f, "threads", s.threads, an_int);
  take(f, "golden_dir", s.golden_dir, a_string);
  take(f, "goldens", s.goldens, a_string);
  take(f, "policy_file", s.policy_file, a_string);
  take(f, "max_slowdown", s.max_slowdown, a_number);
  take(f, "significance", s.significance, a_number);
  take(f, "family_significance", s.family_significance, a_number);
  take(f, "max_exponent_increase", s.max_exponent_increase, a_number);
  take(f, "max_memory_increase", s.max_memory_increase, a_number);
}

json merged_list(const std::vector<MergedShard>& shards) {
  json list = json::array();
  for (const MergedShard& shard : shards) list.push_back(merged_json(shard));
  return list;
}

std::vector<MergedShard> merged_list_from(const JsonField& field) {
  std::vector<MergedShard> shards;
  for (const JsonField& shard : field.elements()) shards.push_back(merged_from(shard));
  return shards;
}

}  // namespace

std::string_view to_string(PinnedBy pinned_by) {
  switch (pinned_by) {
    case PinnedBy::none: return "";
    case PinnedBy::adapter: return "adapter";
    case PinnedBy::option: return "--pin";
  }
  return "";
}

json to_json(const MeasurementSettings& s) {
  json j = json::object();
  put_schedule(j, s);
  put_clocks_and_policy(j, s);
  put(j, "shard", s.shard, shard_json);
  put(j, "merged_shards", s.merged_shards, merged_list);
  if (s.unknown.is_object()) {
    for (const auto& [key, value] : s.unknown.items()) j[key] = value;
  }
  return j;
}

MeasurementSettings settings_from_json(const JsonField& field) {
  MeasurementSettings s;
  if (field.value().is_null()) return s;
  for (const std::string& key : field.keys()) {  // fails unless an object
    if (!known_key(key)) s.unknown[key] = field.member(key).value();
  }
  take_schedule(field, s);
  take_clocks_and_policy(field, s);
  take(field, "shard", s.shard, shard_from);
  take(field, "merged_shards", s.merged_shards, merged_list_from);
  return s;
}

}  // namespace raygate

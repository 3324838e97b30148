// Field by field: a known key is read into its typed field and checked there; any other key is
// kept as it came, so a newer raygate's settings survive a read and write by this one.
#include "results/settings_json.h"

#include <fmt/core.h>

#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/enum_words.h"
#include "results/typed_fields.h"

namespace raygate {
namespace {

using json = nlohmann::json;
using namespace typed_fields;

// Every field with its key, once: the writer, the reader and the list of known keys all walk
// it, so a new setting is a field in measurement_settings.h and a line here.
template <typename Settings, typename Visit>
void each_field(Settings& s, Visit&& visit) {
  visit("schedule", s.schedule);
  visit("warmup_runs", s.warmup_runs);
  visit("pin_cpus", s.pin_cpus);
  visit("pinned_by", s.pinned_by);
  visit("duet_cpus", s.duet_cpus);
  visit("round_cpus", s.round_cpus);
  visit("baseline_rounds", s.baseline_rounds);
  visit("repeats", s.repeats);
  visit("cpu_idle", s.cpu_idle);
  visit("cpu_idle_refused", s.cpu_idle_refused);
  visit("target_relative_half_width", s.target_relative_half_width);
  visit("min_rounds", s.min_rounds);
  visit("max_rounds", s.max_rounds);
  visit("max_seconds_per_scene", s.max_seconds_per_scene);
  visit("max_minutes", s.max_minutes);
  visit("metric", s.metric);
  visit("metric_by_threads", s.metric_by_threads);
  visit("timing_source", s.timing_source);
  visit("tracer_clock", s.tracer_clock);
  visit("baseline_clock", s.baseline_clock);
  visit("unit", s.unit);
  visit("threads", s.threads);
  visit("golden_dir", s.golden_dir);
  visit("goldens", s.goldens);
  visit("images", s.images);
  visit("image_tolerance", s.image_tolerance);
  visit("policy_file", s.policy_file);
  visit("max_slowdown", s.max_slowdown);
  visit("significance", s.significance);
  visit("family_significance", s.family_significance);
  visit("max_exponent_increase", s.max_exponent_increase);
  visit("max_memory_increase", s.max_memory_increase);
  visit("shard", s.shard);
  visit("merged_shards", s.merged_shards);
}

// The range each number of the settings may hold, as the options and the policy file that set it
// bound it (cli/measure_options.cpp, gate/policy.cpp) with room for older raygates: a document
// edited to `max_minutes: -5`, or one whose NaN was written null, is refused where it is read,
// with the setting's path, rather than judged or stored.
struct SettingRange {
  std::string_view key;
  double lowest;
  double highest;
};
constexpr std::array<SettingRange, 15> kSettingRanges{{{"warmup_runs", 0, 1000},
                                                       {"baseline_rounds", 0, 1e6},
                                                       {"repeats", 1, 100},
                                                       {"target_relative_half_width", 0, 1},
                                                       {"min_rounds", 0, 1e6},
                                                       {"max_rounds", 0, 1e6},
                                                       {"max_seconds_per_scene", 0, 1e7},
                                                       {"max_minutes", 0, 1e6},
                                                       {"threads", 0, 1e6},
                                                       {"max_slowdown", 0, 10},
                                                       {"significance", 0.0001, 0.5},
                                                       {"family_significance", 0.0001, 0.5},
                                                       {"max_exponent_increase", 0, 10},
                                                       {"max_memory_increase", 0, 100},
                                                       {"image_tolerance", 0.0001, 1}}};

void check_setting_ranges(const JsonField& settings) {
  for (const SettingRange& range : kSettingRanges) {
    if (!settings.has(range.key)) continue;
    const JsonField field = settings.member(range.key);
    if (field.value().is_null()) {
      field.fail("expected a number, found null (a value that was not finite when written)");
    }
    const double value = field.as_number();
    if (!(value >= range.lowest && value <= range.highest)) {
      field.fail(fmt::format("{} is out of range (from {} to {})", field.value().dump(),
                             range.lowest, range.highest));
    }
  }
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
constexpr std::array<CpuIdle, 2> kIdles{CpuIdle::os, CpuIdle::poll};
constexpr std::array<ImageKind, 2> kImageKinds{ImageKind::deterministic, ImageKind::monte_carlo};

json shard_json(const ShardRecord& record) {
  json j = {{"index", record.spec.index},
            {"count", record.spec.count},
            {"suite_scenes", record.suite_scenes},
            {"cost_basis", record.cost_basis}};
  if (!record.suite_sha256.empty()) j["suite_sha256"] = record.suite_sha256;
  return j;
}

ShardRecord shard_from(const JsonField& j) {
  ShardRecord record;
  record.spec.index = int_of(j.member("index"));
  record.spec.count = int_of(j.member("count"));
  if (j.has("suite_scenes")) record.suite_scenes = string_list(j.member("suite_scenes"));
  // merge finds a missing shard's scenes by this list: a scene twice would be looked for twice.
  for (std::size_t i = 0; i < record.suite_scenes.size(); ++i) {
    const auto& scenes = record.suite_scenes;
    if (std::find(scenes.begin(), scenes.begin() + i, scenes[i]) != scenes.begin() + i) {
      j.member("suite_scenes").fail("scene \"" + scenes[i].substr(0, 80) + "\" is listed twice");
    }
  }
  if (j.has("cost_basis")) {
    record.cost_basis = j.member("cost_basis").as_string();
    // "equal", or the document whose times were the costs (pipeline/measure_options.cpp).
    if (record.cost_basis != "equal" && record.cost_basis.find("sha256:") == std::string::npos) {
      j.member("cost_basis")
          .fail("\"" + record.cost_basis.substr(0, 80) +
                "\" is not a cost basis (\"equal\", or the results "
                "document's sha256:<hex>)");
    }
  }
  if (j.has("suite_sha256")) {
    record.suite_sha256 = j.member("suite_sha256").as_string();
    if (record.suite_sha256.size() != 64 ||
        record.suite_sha256.find_first_not_of("0123456789abcdef") != std::string::npos) {
      j.member("suite_sha256").fail("not a SHA-256 (64 lower-case hex digits)");
    }
  }
  if (record.spec.count < 1 || record.spec.index < 1 || record.spec.index > record.spec.count) {
    j.fail("index " + std::to_string(record.spec.index) + " of count " +
           std::to_string(record.spec.count) + " is not a shard (1 <= index <= count)");
  }
  return record;
}

json merged_json(const MergedShard& m) {
  return {{"index", m.spec.index},      {"count", m.spec.count},
          {"document", m.document},     {"raygate_version", m.raygate_version},
          {"started_at", m.started_at}, {"finished_at", m.finished_at},
          {"complete", m.complete},     {"scenes", m.scenes},
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

// A value as the document writes it: numbers, flags, strings and lists as they are, enums as
// their words, the shard records as objects.
template <typename T>
json value_json(const T& value) {
  return json(value);
}
json value_json(ScheduleKind kind) { return std::string(to_string(kind)); }
json value_json(TimingSource source) { return std::string(to_string(source)); }
json value_json(PinnedBy pinned_by) { return std::string(to_string(pinned_by)); }
json value_json(CpuIdle idle) { return std::string(to_string(idle)); }
json value_json(ImageKind kind) { return std::string(to_string(kind)); }
json value_json(const ShardRecord& record) { return shard_json(record); }
json value_json(const std::vector<MergedShard>& shards) {
  json list = json::array();
  for (const MergedShard& shard : shards) list.push_back(merged_json(shard));
  return list;
}

// A value read into its field, checked on the way (typed_fields.h); a double written null (not
// finite) reads back as NaN.
void read_value(const JsonField& f, std::optional<int>& out) { out = int_of(f); }
void read_value(const JsonField& f, std::optional<std::size_t>& out) { out = count_of(f); }
void read_value(const JsonField& f, std::optional<double>& out) { out = number_or_nan(f); }
void read_value(const JsonField& f, std::optional<bool>& out) { out = f.as_bool(); }
void read_value(const JsonField& f, std::optional<std::string>& out) { out = f.as_string(); }
void read_value(const JsonField& f, std::optional<std::vector<int>>& out) { out = int_list(f); }
void read_value(const JsonField& f, std::optional<ScheduleKind>& out) {
  out = word_from(f, kSchedules, "schedule");
}
void read_value(const JsonField& f, std::optional<TimingSource>& out) {
  out = word_from(f, kSources, "timing source");
}
void read_value(const JsonField& f, std::optional<PinnedBy>& out) {
  out = word_from(f, kPinners, "pinner");
}
void read_value(const JsonField& f, std::optional<CpuIdle>& out) {
  out = word_from(f, kIdles, "cpu idle");
}
void read_value(const JsonField& f, std::optional<ImageKind>& out) {
  out = word_from(f, kImageKinds, "image kind");
}
void read_value(const JsonField& f, std::optional<ShardRecord>& out) { out = shard_from(f); }
void read_value(const JsonField& f, std::optional<std::vector<MergedShard>>& out) {
  out.emplace();
  for (const JsonField& shard : f.elements()) out->push_back(merged_from(shard));
}

}  // namespace

std::string_view to_string(PinnedBy pinned_by) {
  // The words as documents have always written them: the option's own name for --pin.
  constexpr EnumWords<PinnedBy, 3> kWords{
      {{PinnedBy::none, ""}, {PinnedBy::adapter, "adapter"}, {PinnedBy::option, "--pin"}}};
  return word_of(kWords, pinned_by, "");
}

std::string_view to_string(CpuIdle idle) {
  constexpr EnumWords<CpuIdle, 2> kWords{{{CpuIdle::os, "os"}, {CpuIdle::poll, "poll"}}};
  return word_of(kWords, idle, "");
}

json to_json(const MeasurementSettings& s) {
  json j = json::object();
  each_field(s, [&](const char* key, const auto& field) {
    if (field) j[key] = value_json(*field);
  });
  if (s.unknown.is_object()) {
    for (const auto& [key, value] : s.unknown.items()) j[key] = value;
  }
  return j;
}

MeasurementSettings settings_from_json(const JsonField& field) {
  MeasurementSettings s;
  if (field.value().is_null()) return s;
  const std::vector<std::string> keys = field.keys();  // fails unless an object
  std::set<std::string> known;
  each_field(s, [&](const char* key, auto& out) {
    known.insert(key);
    if (field.has(key)) read_value(field.member(key), out);
  });
  check_setting_ranges(field);
  for (const std::string& key : keys) {
    if (!known.contains(key)) s.unknown[key] = field.member(key).value();
  }
  return s;
}

}  // namespace raygate

// JSON form of the results document. Field names are the document's public schema
// (docs/results-format.md); change them only with a schema_version bump and a migration.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>
#include <initializer_list>

#include "core/error.h"
#include "core/fs.h"
#include "core/json_field.h"
#include "core/json_reader.h"
#include "results/json_number.h"
#include "results/results_check.h"
#include "results/results.h"
#include "results/scaling_json.h"
#include "results/settings_json.h"

namespace raygate {

namespace {

using nlohmann::json;

// Non-finite numbers have no JSON form: they are written as null and read back as `if_null`.
double number_at(const json& object, const char* key, double if_null = 0.0) {
  const json& value = object.at(key);
  return value.is_null() ? if_null : value.get<double>();
}

// A word of the document's vocabulary read as its enum (core/domain.h): results_check.cpp has
// already refused unknown words, so this names the field only for a document built in memory.
template <typename Enum>
Enum word_at(const json& object, const char* key,
             std::optional<Enum> (*parse)(std::string_view), const char* field) {
  const std::string word = object.at(key).get<std::string>();
  const std::optional<Enum> value = parse(word);
  if (!value) throw std::invalid_argument(fmt::format("{}: unknown word \"{}\"", field, word));
  return *value;
}

std::string word(auto value) { return std::string(to_string(value)); }

// Members named in one list, so a record's fields are spelled once each: numbers written null
// when not finite and read back by number_at, strings read as they are.
using NumberFields = std::initializer_list<std::pair<const char*, double>>;
using NumberTargets = std::initializer_list<std::pair<const char*, double*>>;
using StringTargets = std::initializer_list<std::pair<const char*, std::string*>>;

json finite_numbers(NumberFields fields) {
  json j = json::object();
  for (const auto& [key, value] : fields) j[key] = finite_number(value);
  return j;
}

void read_numbers(const json& j, NumberTargets targets) {
  for (const auto& [key, target] : targets) *target = number_at(j, key);
}

void read_strings(const json& j, StringTargets targets) {
  for (const auto& [key, target] : targets) *target = j.at(key).get<std::string>();
}

json path_list(const std::vector<std::filesystem::path>& paths) {
  json out = json::array();
  for (const auto& path : paths) out.push_back(path.string());
  return out;
}

}  // namespace

void to_json(json& j, const Interval& interval) {
  j = json{{"lower", finite_number(interval.lower)}, {"upper", finite_number(interval.upper)}};
}
// A bound written as null was not finite: the interval is unbounded on that side. Read as 0 it
// would say the opposite (an upper bound of +inf read back as 0 put lower above upper; found by
// fuzzing the round trip, tests/fuzz/corpus/results/found-null-upper.json).
void from_json(const json& j, Interval& interval) {
  interval.lower = number_at(j, "lower", -std::numeric_limits<double>::infinity());
  interval.upper = number_at(j, "upper", std::numeric_limits<double>::infinity());
}

void to_json(json& j, const RatioSummary& r) {
  j = finite_numbers({{"normalized_ratio", r.ratio},
                      {"relative_half_width", r.relative_half_width},
                      {"log_ratio_median", r.log_ratio_median},
                      {"log_ratio_mad_scaled", r.log_ratio_mad_scaled},
                      {"tracer_median_seconds", r.tracer_median_seconds},
                      {"baseline_median_seconds", r.baseline_median_seconds}});
  j["rounds"] = r.rounds;
  j["ratio_interval"] = r.ratio_interval;
}
void from_json(const json& j, RatioSummary& r) {
  r.rounds = j.at("rounds").get<std::size_t>();
  r.ratio_interval = j.at("ratio_interval").get<Interval>();
  read_numbers(j, {{"normalized_ratio", &r.ratio},
                   {"relative_half_width", &r.relative_half_width},
                   {"log_ratio_median", &r.log_ratio_median},
                   {"log_ratio_mad_scaled", &r.log_ratio_mad_scaled},
                   {"tracer_median_seconds", &r.tracer_median_seconds},
                   {"baseline_median_seconds", &r.baseline_median_seconds}});
}

void to_json(json& j, const SuiteScore& s) {
  j = json{{"scenes", s.scenes}, {"score", finite_number(s.score)}, {"interval", s.interval}};
}
void from_json(const json& j, SuiteScore& s) {
  s.scenes = j.at("scenes").get<std::size_t>();
  s.score = number_at(j, "score");
  s.interval = j.at("interval").get<Interval>();
}

void to_json(json& j, const ChangeSummary& c) {
  j = json{{"rounds", c.rounds},
           {"change", finite_number(c.change)},
           {"change_interval", c.change_interval},
           {"confidence", finite_number(c.confidence)},
           {"interval_kind", std::string(to_string(c.interval_kind))},
           {"log_change_median", finite_number(c.log_change_median)},
           {"log_change_mad_scaled", finite_number(c.log_change_mad_scaled)},
           {"base", c.base},
           {"head", c.head},
           {"mann_whitney",
            {{"u", finite_number(c.mann_whitney.u)},
             {"z", finite_number(c.mann_whitney.z)},
             {"p_value", finite_number(c.mann_whitney.p_value)}}}};
  if (c.exact) j["exact"] = true;  // --timing sim with identical counts: no interval needed
  if (c.interval_kind == ChangeIntervalKind::confidence_sequence) {
    j["equivalence_interval"] = c.equivalence_interval;
    j["equivalence_confidence"] = finite_number(c.equivalence_confidence);
    j["one_look_interval"] = c.one_look_interval;
    j["one_look_confidence"] = finite_number(c.one_look_confidence);
  }
}
void from_json(const json& j, ChangeSummary& c) {
  c.rounds = j.at("rounds").get<std::size_t>();
  c.change = number_at(j, "change");
  c.change_interval = j.at("change_interval").get<Interval>();
  c.confidence = j.value("confidence", 0.95);  // documents before it was recorded: 95%
  // Documents before the confidence sequence carried the one-look interval.
  const std::string kind = j.value("interval_kind", std::string("order-statistic"));
  const std::optional<ChangeIntervalKind> parsed = change_interval_kind(kind);
  if (!parsed) {
    throw std::invalid_argument("change.interval_kind: unknown interval \"" + kind +
                                "\" (order-statistic or confidence-sequence)");
  }
  c.interval_kind = *parsed;
  if (c.interval_kind == ChangeIntervalKind::confidence_sequence) {
    c.equivalence_interval = j.at("equivalence_interval").get<Interval>();
    c.equivalence_confidence = number_at(j, "equivalence_confidence");
    c.one_look_interval = j.at("one_look_interval").get<Interval>();
    c.one_look_confidence = number_at(j, "one_look_confidence");
  }
  c.log_change_median = number_at(j, "log_change_median");
  c.log_change_mad_scaled = number_at(j, "log_change_mad_scaled");
  c.base = j.at("base").get<RatioSummary>();
  c.head = j.at("head").get<RatioSummary>();
  const json& mw = j.at("mann_whitney");
  c.mann_whitney = {number_at(mw, "u"), number_at(mw, "z"), number_at(mw, "p_value", 1.0)};
  c.exact = j.value("exact", false);
}

void to_json(json& j, const ImageMetrics& m) {
  j = json{{"size_mismatch", m.size_mismatch},
           {"width", m.width},
           {"height", m.height},
           {"expected_width", m.expected_width},
           {"expected_height", m.expected_height},
           {"mean_error", finite_number(m.mean_error)},
           {"rms_error", finite_number(m.rms_error)},
           {"psnr_db", finite_number(m.psnr_db)},  // null: identical images (infinite PSNR)
           {"max_error", finite_number(m.max_error)},
           {"max_pixel", {m.max_x, m.max_y, m.max_channel}},
           {"max_actual_value", finite_number(m.max_actual_value)},
           {"max_expected_value", finite_number(m.max_expected_value)},
           {"pixels_over_warn", m.pixels_over_warn},
           {"pixels_over_fail", m.pixels_over_fail},
           {"percent_over_fail", finite_number(m.percent_over_fail)},
           {"mean_luminance_actual", finite_number(m.mean_luminance_actual)},
           {"mean_luminance_expected", finite_number(m.mean_luminance_expected)},
           {"nonfinite_values", m.nonfinite_values},
           {"nonfinite_pixels", m.nonfinite_pixels},
           {"first_nonfinite_pixel", {m.nonfinite_x, m.nonfinite_y}},
           {"expected_nonfinite_pixels", m.expected_nonfinite_pixels}};
}
void from_json(const json& j, ImageMetrics& m) {
  m.size_mismatch = j.at("size_mismatch").get<bool>();
  m.width = j.at("width").get<int>();
  m.height = j.at("height").get<int>();
  m.expected_width = j.at("expected_width").get<int>();
  m.expected_height = j.at("expected_height").get<int>();
  m.mean_error = number_at(j, "mean_error");
  m.rms_error = number_at(j, "rms_error");
  m.psnr_db = number_at(j, "psnr_db", std::numeric_limits<double>::infinity());
  m.max_error = number_at(j, "max_error");
  const json& pixel = j.at("max_pixel");
  m.max_x = pixel.at(0).get<int>();
  m.max_y = pixel.at(1).get<int>();
  m.max_channel = pixel.at(2).get<int>();
  m.max_actual_value = number_at(j, "max_actual_value");
  m.max_expected_value = number_at(j, "max_expected_value");
  m.pixels_over_warn = j.at("pixels_over_warn").get<long>();
  m.pixels_over_fail = j.at("pixels_over_fail").get<long>();
  m.percent_over_fail = number_at(j, "percent_over_fail");
  m.mean_luminance_actual = number_at(j, "mean_luminance_actual");
  m.mean_luminance_expected = number_at(j, "mean_luminance_expected");
  m.nonfinite_values = j.at("nonfinite_values").get<long>();
  // Absent from documents written before NaN pixels were counted.
  m.nonfinite_pixels = j.value("nonfinite_pixels", 0L);
  const json first = j.value("first_nonfinite_pixel", json::array({0, 0}));
  m.nonfinite_x = first.at(0).get<int>();
  m.nonfinite_y = first.at(1).get<int>();
  m.expected_nonfinite_pixels = j.value("expected_nonfinite_pixels", 0L);
}

void to_json(json& j, const Worktree& w) {
  j = json{{"path", w.path.string()},       {"revision", w.revision}, {"ref_name", w.ref_name},
           {"sha", w.sha},                  {"short_sha", w.short_sha}, {"subject", w.subject},
           {"author", w.author},            {"commit_time", w.commit_time}, {"dirty", w.dirty}};
}
void from_json(const json& j, Worktree& w) {
  w.path = j.at("path").get<std::string>();
  read_strings(j, {{"revision", &w.revision}, {"ref_name", &w.ref_name}, {"sha", &w.sha},
                   {"short_sha", &w.short_sha}, {"subject", &w.subject}, {"author", &w.author},
                   {"commit_time", &w.commit_time}});
  w.dirty = j.at("dirty").get<bool>();
}

void to_json(json& j, const SuiteScene& s) {
  j = json{{"id", s.id}, {"scene", s.scene}, {"size", s.size}, {"width", s.width},
           {"height", s.height}};
}
void from_json(const json& j, SuiteScene& s) {
  s.id = j.at("id").get<std::string>();
  s.scene = j.at("scene").get<std::string>();
  s.size = j.at("size").get<int>();
  s.width = j.at("width").get<int>();
  s.height = j.at("height").get<int>();
}

void to_json(json& j, const Round& r) { j = json{{"order", r.order}, {"runs", r.runs}}; }
void from_json(const json& j, Round& r) {
  r.order = j.at("order").get<std::vector<std::string>>();
  r.runs = j.at("runs").get<std::map<std::string, RunRecord>>();
}

void to_json(json& j, const ImageCheck& c) {
  j = json{{"role", word(c.role)},
           {"reference", word(c.reference)},
           {"actual", c.actual.string()},
           {"expected", c.expected.string()},
           {"verdict", word(c.verdict)},
           {"metrics", nullptr},
           {"evidence", path_list(c.evidence)}};
  if (c.metrics) j["metrics"] = *c.metrics;
  if (!c.error.empty()) j["error"] = c.error;
}
void from_json(const json& j, ImageCheck& c) {
  c.role = word_at(j, "role", parse_role, "images.role");
  c.reference = word_at(j, "reference", parse_image_reference, "images.reference");
  c.actual = j.at("actual").get<std::string>();
  c.expected = j.at("expected").get<std::string>();
  const std::string verdict = j.at("verdict").get<std::string>();
  const std::optional<ImageVerdict> parsed = parse_image_verdict(verdict);
  if (!parsed) {
    throw std::invalid_argument("images.verdict: unknown image verdict \"" + verdict +
                                "\" (pass, warn, fail, missing or error)");
  }
  c.verdict = *parsed;
  c.error = j.value("error", std::string());
  if (!j.at("metrics").is_null()) c.metrics = j.at("metrics").get<ImageMetrics>();
  for (const json& path : j.at("evidence")) c.evidence.emplace_back(path.get<std::string>());
}

void to_json(json& j, const SceneResult& s) {
  j = json{{"scene", s.entry},
           {"scene_sha256", s.scene_sha256},
           {"status", word(s.status)},
           {"stop_reason", s.runs.stop_reason},
           {"seconds_spent", finite_number(s.runs.seconds_spent)},
           {"failure", nullptr},
           {"warmup", s.runs.warmup},
           {"rounds", s.runs.rounds},
           {"ratios", s.ratios},
           {"change", nullptr},
           {"images", s.images}};
  if (s.runs.failed_run) {
    j["failure"] = {{"role", word(s.runs.failed_role)}, {"run", *s.runs.failed_run}};
  }
  if (!s.runs.partial_round.empty()) j["partial_round"] = s.runs.partial_round;
  if (s.change) {
    j["change"] = *s.change;
    j["change"]["verdict"] = word(s.change_verdict);
  }
  if (s.explanation) j["explanation"] = *s.explanation;  // only when there is one (issue 27)
}
void from_json(const json& j, SceneResult& s) {
  s.entry = j.at("scene").get<SuiteScene>();
  s.scene_sha256 = j.at("scene_sha256").get<std::string>();
  s.status = word_at(j, "status", parse_scene_status, "scenes.status");
  s.runs.stop_reason = j.at("stop_reason").get<std::string>();
  s.runs.seconds_spent = number_at(j, "seconds_spent");
  if (const json& failure = j.at("failure"); !failure.is_null()) {
    s.runs.failed_role = word_at(failure, "role", parse_role, "failure.role");
    s.runs.failed_run = failure.at("run").get<RunRecord>();
  }
  s.runs.warmup = j.at("warmup").get<std::map<std::string, std::vector<RunRecord>>>();
  s.runs.rounds = j.at("rounds").get<std::vector<Round>>();
  if (j.contains("partial_round")) {
    s.runs.partial_round = j.at("partial_round").get<std::map<std::string, RunRecord>>();
  }
  s.ratios = j.at("ratios").get<std::map<std::string, RatioSummary>>();
  if (const json& change = j.at("change"); !change.is_null()) {
    s.change = change.get<ChangeSummary>();
    s.change_verdict = word_at(change, "verdict", change_verdict_named, "change.verdict");
  }
  s.images = j.at("images").get<std::vector<ImageCheck>>();
  if (const auto found = j.find("explanation"); found != j.end()) {
    s.explanation = found->get<Explanation>();
  }
}

void to_json(json& j, const RevisionRecord& r) {
  j = json{{"role", word(r.role)},
           {"repository", r.repository},
           {"worktree", r.worktree},
           {"adapter", {{"name", r.adapter_name}, {"hash", r.adapter_hash}, {"file", r.adapter_file}}},
           {"build", build_record_to_json(r.build)}};
  // Written only when known, so a document from before it was recorded reads back and hashes
  // the same (the store's duplicate check compares canonical JSON).
  if (!r.repository_id.empty()) j["repository_id"] = r.repository_id;
  if (!r.adapter_measurement.empty()) j["adapter"]["measurement"] = r.adapter_measurement;
}
void from_json(const json& j, RevisionRecord& r) {
  r.role = word_at(j, "role", parse_role, "revisions.role");
  r.repository = j.at("repository").get<std::string>();
  if (j.contains("repository_id")) r.repository_id = j.at("repository_id").get<std::string>();
  r.worktree = j.at("worktree").get<Worktree>();
  const json& adapter = j.at("adapter");
  r.adapter_name = adapter.at("name").get<std::string>();
  r.adapter_hash = adapter.at("hash").get<std::string>();
  r.adapter_file = adapter.at("file").get<std::string>();
  if (adapter.contains("measurement")) {
    r.adapter_measurement = adapter.at("measurement").get<std::string>();
  }
  r.build = build_record_from_json(j.at("build"));
}

void to_json(json& j, const BaselineRecord& b) {
  j = json{{"version", b.version}, {"source_sha256", b.source_sha256}, {"accel", b.accel},
           {"sampling", b.sampling}, {"timing", b.timing}};
}
void from_json(const json& j, BaselineRecord& b) {
  read_strings(j, {{"version", &b.version}, {"source_sha256", &b.source_sha256},
                   {"accel", &b.accel}, {"sampling", &b.sampling}, {"timing", &b.timing}});
}

const RatioSummary* SceneResult::ratio(Role role) const {
  const auto found = ratios.find(role_name(role));
  return found == ratios.end() ? nullptr : &found->second;
}

const RevisionRecord* ResultsDocument::revision(Role role) const {
  for (const RevisionRecord& r : revisions) {
    if (r.role == role) return &r;
  }
  return nullptr;
}

nlohmann::json to_json(const ResultsDocument& d) {
  json j{{"schema_version", d.schema_version},
              {"kind", word(d.kind)},
              {"raygate_version", d.raygate_version},
              {"started_at", d.started_at},
              {"finished_at", d.finished_at},
              {"complete", d.complete},
              {"machine", d.machine},
              {"baseline", d.baseline},
              {"suite", d.suite},
              {"shard", d.shard},
              {"settings", to_json(d.settings)},
              {"revisions", d.revisions},
              {"scenes", d.scenes},
              {"scores", d.scores}};
  if (d.scaling) j["scaling"] = to_json(*d.scaling);
  return j;
}

namespace {

// The schema_version a document says it has; a file without one is not a results document at all
// (a suite, a policy, a report's JSON given by mistake), which the message says first.
int schema_version_of(const nlohmann::json& j, const std::string& origin) {
  try {
    if (!j.is_object()) throw FieldError("$", "expected an object, found " + describe_json(j));
    const JsonField field = JsonField(j, "$").member("schema_version");
    const long long version = field.as_integer();
    if (version < 1) field.fail("expected 1 or more, found " + describe_json(field.value()));
    return static_cast<int>(std::min<long long>(version, 1'000'000));
  } catch (const FieldError& e) {
    throw UsageError(origin + ": not a raygate results document: " + e.path() + ": " + e.what());
  }
}

}  // namespace

ResultsDocument results_from_json(const nlohmann::json& j, const std::string& origin) {
  try {
    const int version = schema_version_of(j, origin);
    if (version > kResultsSchemaVersion) {
      throw UsageError(fmt::format("{}: results schema_version {} is newer than this raygate "
                                   "reads ({}); upgrade raygate",
                                   origin, version, kResultsSchemaVersion));
    }
    // Every field checked before any is taken, so what follows cannot meet a wrong type.
    check_results_json(j);
    ResultsDocument d;
    d.schema_version = version;
    d.kind = word_at(j, "kind", parse_document_kind, "kind");
    d.raygate_version = j.at("raygate_version").get<std::string>();
    d.started_at = j.at("started_at").get<std::string>();
    d.finished_at = j.at("finished_at").get<std::string>();
    d.complete = j.at("complete").get<bool>();
    d.machine = j.at("machine");
    d.baseline = j.at("baseline").get<BaselineRecord>();
    d.suite = j.at("suite").get<std::string>();
    d.shard = j.value("shard", std::string());
    const JsonField root(j, "$");
    d.settings = settings_from_json(root.member("settings"));
    d.revisions = j.at("revisions").get<std::vector<RevisionRecord>>();
    d.scenes = j.at("scenes").get<std::vector<SceneResult>>();
    d.scores = j.at("scores").get<std::map<std::string, SuiteScore>>();
    if (root.has("scaling") && !j.at("scaling").is_null()) {
      d.scaling = scaling_from_json(root.member("scaling"));
    }
    return d;
  } catch (const FieldError& e) {
    throw UsageError(origin + ": " + e.path() + ": " + e.what());
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(origin + ": not a raygate results document: " + e.what());
  } catch (const std::invalid_argument& e) {  // a field of a known name with an unknown value
    throw UsageError(origin + ": " + e.what());
  }
}

void write_results(const ResultsDocument& document, const std::filesystem::path& path) {
  write_file_atomically(path, to_json(document).dump(1) + "\n");
}

ResultsDocument read_results(const std::filesystem::path& path) {
  // Duplicate keys and out-of-range numbers refused with where they are (core/json_reader.h).
  return results_from_json(read_json_file(path), path.string());
}

}  // namespace raygate

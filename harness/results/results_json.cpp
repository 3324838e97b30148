// JSON form of the results document. Field names are the document's public schema
// (docs/results-format.md); change them only with a schema_version bump and a migration.
#include <fmt/core.h>

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "core/error.h"
#include "core/fs.h"
#include "core/json_field.h"
#include "core/json_reader.h"
#include "results/json_number.h"
#include "results/json_record.h"
#include "results/results_check.h"
#include "results/results.h"
#include "results/scaling_json.h"
#include "results/settings_json.h"
#include "results/summary_json.h"
#include "results/typed_fields.h"

namespace raygate {

namespace {

using nlohmann::json;
using json_record::number_at;
using json_record::read_strings;

// A word of the document's vocabulary read as its enum (core/domain.h): results_check.cpp has
// already refused unknown words, so this names the field only for a document built in memory.
template <typename Enum>
Enum word_at(const json& object, const char* key, std::optional<Enum> (*parse)(std::string_view),
             const char* field) {
  const std::string word = object.at(key).get<std::string>();
  const std::optional<Enum> value = parse(word);
  if (!value) throw std::invalid_argument(fmt::format("{}: unknown word \"{}\"", field, word));
  return *value;
}

std::string word(auto value) { return std::string(to_string(value)); }

json path_list(const std::vector<std::filesystem::path>& paths) {
  json out = json::array();
  for (const auto& path : paths) out.push_back(path.string());
  return out;
}

}  // namespace

void to_json(json& j, const Worktree& w) {
  j = json{{"path", w.path.string()},  {"revision", w.revision},
           {"ref_name", w.ref_name},   {"sha", w.sha},
           {"short_sha", w.short_sha}, {"subject", w.subject},
           {"author", w.author},       {"commit_time", w.commit_time},
           {"dirty", w.dirty}};
}
void from_json(const json& j, Worktree& w) {
  w.path = j.at("path").get<std::string>();
  read_strings(j, {{"revision", &w.revision},
                   {"ref_name", &w.ref_name},
                   {"sha", &w.sha},
                   {"short_sha", &w.short_sha},
                   {"subject", &w.subject},
                   {"author", &w.author},
                   {"commit_time", &w.commit_time}});
  w.dirty = j.at("dirty").get<bool>();
}

void to_json(json& j, const SuiteScene& s) {
  j = json{
      {"id", s.id}, {"scene", s.scene}, {"size", s.size}, {"width", s.width}, {"height", s.height}};
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
  if (c.noisy) j["monte_carlo"] = *c.noisy;
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
                                "\" (pass, warn, inconclusive, fail, missing or error)");
  }
  c.verdict = *parsed;
  c.error = j.value("error", std::string());
  if (!j.at("metrics").is_null()) c.metrics = j.at("metrics").get<ImageMetrics>();
  // Absent in documents from before it: their Monte Carlo verdicts are words in `error`.
  if (j.contains("monte_carlo")) c.noisy = j.at("monte_carlo").get<NoisyComparison>();
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
           {"ratios", typed_fields::role_object(s.ratios, typed_fields::record_json<RatioSummary>)},
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

namespace {

// Read with its JSON path, so a ratio under a word that names no role is refused where it is.
SceneResult scene_from(const JsonField& field) {
  const json& j = field.value();
  SceneResult s;
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
  s.ratios = typed_fields::by_role(field.member("ratios"), typed_fields::record_of<RatioSummary>);
  if (const json& change = j.at("change"); !change.is_null()) {
    s.change = change.get<ChangeSummary>();
    s.change_verdict = word_at(change, "verdict", change_verdict_named, "change.verdict");
  }
  s.images = j.at("images").get<std::vector<ImageCheck>>();
  if (const auto found = j.find("explanation"); found != j.end()) {
    s.explanation = found->get<Explanation>();
  }
  return s;
}

}  // namespace

void to_json(json& j, const RevisionRecord& r) {
  j = json{
      {"role", word(r.role)},
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
  j = json{{"version", b.version},
           {"source_sha256", b.source_sha256},
           {"accel", b.accel},
           {"sampling", b.sampling},
           {"timing", b.timing}};
}
void from_json(const json& j, BaselineRecord& b) {
  read_strings(j, {{"version", &b.version},
                   {"source_sha256", &b.source_sha256},
                   {"accel", &b.accel},
                   {"sampling", &b.sampling},
                   {"timing", &b.timing}});
}

const RatioSummary* SceneResult::ratio(Role role) const {
  const auto found = ratios.find(role);
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
         {"scores", typed_fields::role_object(d.scores, typed_fields::record_json<SuiteScore>)}};
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
      throw UsageError(
          fmt::format("{}: results schema_version {} is newer than this raygate "
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
    for (const JsonField& scene : root.member("scenes").elements()) {
      d.scenes.push_back(scene_from(scene));
    }
    d.scores = typed_fields::by_role(root.member("scores"), typed_fields::record_of<SuiteScore>);
    if (root.has("scaling") && !j.at("scaling").is_null()) {
      d.scaling = scaling_from_json(root.member("scaling"));
    }
    return d;
  } catch (const FieldError& e) {
    throw UsageError(origin + ": " + e.path() + ": " + e.what());
  } catch (const nlohmann::json::exception& e) {
    throw UsageError(origin + ": not a raygate results document: " + plain_exception_text(e));
  } catch (const std::invalid_argument& e) {  // a field of a known name with an unknown value
    throw UsageError(origin + ": " + e.what());
  }
}

void write_results(const ResultsDocument& document, const std::filesystem::path& path) {
  // A byte that is not UTF-8 (a path from a folder named in Latin-1) is written as U+FFFD: the
  // document is kept, not lost to nlohmann's type_error.316 after the measuring.
  write_file_atomically(
      path, to_json(document).dump(1, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

ResultsDocument read_results(const std::filesystem::path& path) {
  // Duplicate keys and out-of-range numbers refused with where they are (core/json_reader.h).
  return results_from_json(read_json_file(path), path.string());
}

}  // namespace raygate

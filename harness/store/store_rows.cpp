// Rows of the store's tables for one results document, shared by every backend.
#include "store/store_rows.h"

#include <fmt/core.h>

#include <cctype>
#include <cmath>
#include <limits>

#include "core/error.h"
#include "core/json_reader.h"
#include "core/sanitize.h"
#include "core/sha256.h"
#include "core/utf8.h"
#include "compare/image_verdict.h"
#include "gate/memory_gate.h"
#include "results/series.h"

namespace raygate {

namespace {

std::optional<double> finite(double value) {
  return std::isfinite(value) ? std::optional<double>(value) : std::nullopt;
}

std::string text_at(const nlohmann::json& object, const char* key) {
  if (!object.is_object()) return {};
  const auto found = object.find(key);
  return found != object.end() && found->is_string() ? found->get<std::string>() : std::string();
}

RevisionRow revision_row(const RevisionRecord& r) {
  RevisionRow row;
  row.role = role_name(r.role);
  row.repository = r.repository;
  row.sha = r.worktree.sha;
  row.short_sha = r.worktree.short_sha;
  row.subject = r.worktree.subject;
  row.author = r.worktree.author;
  row.ref_name = r.worktree.ref_name;
  row.commit_time = r.worktree.commit_time;
  row.commit_unix = parse_iso8601_unix(r.worktree.commit_time);
  row.dirty = r.worktree.dirty;
  row.adapter_name = r.adapter_name;
  row.adapter_hash = r.adapter_hash;
  row.repository_key = repository_key(r);
  return row;
}

const ImageCheck* golden_check(const SceneResult& scene, Role role) {
  for (const ImageCheck& check : scene.images) {
    if (check.role == role && check.reference == ImageReference::golden) return &check;
  }
  return nullptr;
}

void fill_ratio(SceneRow& row, const RatioSummary& r) {
  row.rounds = static_cast<std::int64_t>(r.rounds);
  // A ratio of no rounds (null in the document, read back as 0) is no ratio: NULL, as the
  // reader below refuses a stored ratio that is not above 0.
  row.ratio = r.rounds > 0 && r.ratio > 0.0 ? finite(r.ratio) : std::nullopt;
  row.ratio_lower = finite(r.ratio_interval.lower);
  row.ratio_upper = finite(r.ratio_interval.upper);
  row.tracer_median_seconds = finite(r.tracer_median_seconds);
  row.baseline_median_seconds = finite(r.baseline_median_seconds);
}

void fill_image(SceneRow& row, const ImageCheck& check) {
  row.image_verdict = to_string(check.verdict);
  if (!check.metrics) return;
  row.image_max_error = finite(check.metrics->max_error);
  row.image_rms_error = finite(check.metrics->rms_error);
}

// The change is head's against base: stored on head's row.
void fill_change(SceneRow& row, const SceneResult& scene, Role role) {
  if (!scene.change || role != Role::head) return;
  row.change = finite(scene.change->change);
  row.change_lower = finite(scene.change->change_interval.lower);
  row.change_upper = finite(scene.change->change_interval.upper);
  row.change_verdict = to_string(scene.change_verdict);
}

// The limit the document was measured with: its settings say the policy's default.
double recorded_memory_limit(const ResultsDocument& document) {
  return document.settings.max_memory_increase.value_or(kDefaultMaxMemoryIncrease);
}

void fill_memory(SceneRow& row, const ResultsDocument& document, const SceneResult& scene,
                 Role role) {
  if (const std::optional<double> peak = median_peak_kib(scene.runs, role)) {
    row.peak_memory_kib = finite(*peak);
  }
  if (role != Role::head) return;
  const std::optional<MemorySummary> memory = scene_memory(scene);
  if (!memory) return;
  row.memory_change = finite(memory->change);
  row.memory_verdict =
      std::string(to_string(classify_memory(*memory, recorded_memory_limit(document))));
}

SceneRow scene_row(const ResultsDocument& document, const SceneResult& scene,
                   const RevisionRecord& revision) {
  const Role role = revision.role;
  SceneRow row;
  row.scene_id = scene.entry.id;
  row.role = role_name(role);
  row.scene_settings = scene_settings(scene.entry, document.baseline);
  row.series_id = series_key(document, revision, scene).id();
  row.status = to_string(scene.status);
  if (const RatioSummary* ratio = scene.ratio(role)) fill_ratio(row, *ratio);
  if (const ImageCheck* check = golden_check(scene, role)) fill_image(row, *check);
  fill_change(row, scene, role);
  fill_memory(row, document, scene, role);
  return row;
}

DocumentRow document_row(const ResultsDocument& d, const std::string& branch,
                         const std::string& stored_at) {
  DocumentRow row;
  row.document_json = canonical_json(d);
  row.content_sha256 = sha256_hex(row.document_json);
  row.schema_version = d.schema_version;
  row.kind = to_string(d.kind);
  row.branch = branch;
  row.suite = d.suite;
  row.shard = d.shard;
  row.complete = d.complete;
  row.started_at = d.started_at;
  row.finished_at = d.finished_at;
  row.stored_at = stored_at;
  row.raygate_version = d.raygate_version;
  row.baseline_version = d.baseline.version;
  row.baseline_sha256 = d.baseline.source_sha256;
  row.machine_hostname = text_at(d.machine, "hostname");
  row.machine_cpu_model = text_at(d.machine, "cpu_model");
  row.timing = timing_identity(d);
  row.baseline_accel = d.baseline.accel;
  return row;
}

// Parses `count` digits at text[pos], advancing pos; -1 when they are not all digits.
int digits(std::string_view text, std::size_t& pos, std::size_t count) {
  if (pos + count > text.size()) return -1;
  int value = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const char c = text[pos + i];
    if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
    value = value * 10 + (c - '0');
  }
  pos += count;
  return value;
}

bool expect(std::string_view text, std::size_t& pos, char c) {
  if (pos >= text.size() || text[pos] != c) return false;
  ++pos;
  return true;
}

// Days from 1970-01-01 to the civil date (Howard Hinnant's days_from_civil).
std::int64_t days_from_civil(std::int64_t y, unsigned m, unsigned d) {
  y -= m <= 2 ? 1 : 0;
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const auto yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m > 2 ? m - 3 : m + 9) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<std::int64_t>(doe) - 719468;
}

// "Z", "+HH:MM", "+HHMM", "-HH:MM": seconds east of UTC; nullopt if malformed.
std::optional<int> offset_seconds(std::string_view text, std::size_t pos) {
  if (pos < text.size() && text[pos] == 'Z') {
    return pos + 1 == text.size() ? std::optional<int>(0) : std::nullopt;
  }
  if (pos >= text.size() || (text[pos] != '+' && text[pos] != '-')) return std::nullopt;
  const int sign = text[pos++] == '-' ? -1 : 1;
  const int hours = digits(text, pos, 2);
  if (pos < text.size() && text[pos] == ':') ++pos;
  const int minutes = digits(text, pos, 2);
  if (hours < 0 || minutes < 0 || pos != text.size()) return std::nullopt;
  return sign * (hours * 3600 + minutes * 60);
}

}  // namespace

std::string canonical_json(const ResultsDocument& document) {
  return to_json(document).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
}

DocumentRows document_rows(const ResultsDocument& document, const std::string& branch,
                           const std::string& stored_at) {
  DocumentRows rows;
  rows.document = document_row(document, branch, stored_at);
  for (const RevisionRecord& revision : document.revisions) {
    rows.revisions.push_back(revision_row(revision));
  }
  for (const SceneResult& scene : document.scenes) {
    for (const RevisionRecord& revision : document.revisions) {
      rows.scenes.push_back(scene_row(document, scene, revision));
    }
  }
  return rows;
}

StoredSeries stored_series(const std::string& document_json, std::int64_t id) {
  StoredSeries out;
  try {
    const ResultsDocument document =
        results_from_json(nlohmann::json::parse(document_json), fmt::format("document {}", id));
    out.rows = document_rows(document, "", "");
    out.known = true;
  } catch (const std::exception&) {  // not JSON, or not a document this raygate reads
    out.known = false;
  }
  return out;
}

std::optional<std::int64_t> parse_iso8601_unix(std::string_view text) {
  std::size_t pos = 0;
  const int year = digits(text, pos, 4);
  const bool date_ok = expect(text, pos, '-');
  const int month = digits(text, pos, 2);
  const bool date_ok2 = expect(text, pos, '-');
  const int day = digits(text, pos, 2);
  const bool t_ok = expect(text, pos, 'T');
  const int hour = digits(text, pos, 2);
  const bool c1 = expect(text, pos, ':');
  const int minute = digits(text, pos, 2);
  const bool c2 = expect(text, pos, ':');
  const int second = digits(text, pos, 2);
  if (!date_ok || !date_ok2 || !t_ok || !c1 || !c2 || year < 0 || month < 1 || month > 12 ||
      day < 1 || day > 31 || hour < 0 || hour > 23 || minute < 0 || minute > 59 || second < 0 ||
      second > 60) {
    return std::nullopt;
  }
  if (pos < text.size() && text[pos] == '.') {
    ++pos;
    while (pos < text.size() && std::isdigit(static_cast<unsigned char>(text[pos]))) ++pos;
  }
  const std::optional<int> offset = offset_seconds(text, pos);
  if (!offset) return std::nullopt;
  const std::int64_t days =
      days_from_civil(year, static_cast<unsigned>(month), static_cast<unsigned>(day));
  return days * 86400 + hour * 3600 + minute * 60 + second - *offset;
}

std::string short_ref_name(const std::string& ref_name) {
  for (const std::string_view prefix : {"refs/heads/", "refs/remotes/", "refs/tags/", "refs/"}) {
    if (ref_name.starts_with(prefix)) return ref_name.substr(prefix.size());
  }
  return ref_name;
}

void check_history_row(const HistoryRow& row, const std::string& location) {
  // Above 0 where the value is a measured time or a ratio of two; at least 0 where a document may
  // hold 0 (an interval's end, an image error, an unmeasured median).
  // An image's error has no bound but a double's: a pixel of 1e20 is a real (broken) render.
  const auto check = [&](const char* column, const std::optional<double>& value, bool positive,
                         double most = 1e18) {  // results_check's kMaxMeasure
    if (!value) return;
    const bool sense =
        std::isfinite(*value) && *value <= most && (positive ? *value > 0.0 : *value >= 0.0);
    if (sense) return;
    throw InfraError(fmt::format(
        "results store {}: document {}, scene {}: {} is {:.6g}, which no measurement gives; the "
        "store is damaged (rebuild it: raygate import its results documents into a new store)",
        location, row.document_id, row.scene_id, column, *value));
  };
  check("normalized_ratio", row.ratio, true);
  check("ratio_lower", row.ratio_lower, false);
  check("ratio_upper", row.ratio_upper, false);
  check("baseline_median_seconds", row.baseline_median_seconds, false);
  check("image_max_error", row.image_max_error, false, std::numeric_limits<double>::max());
  check("image_rms_error", row.image_rms_error, false, std::numeric_limits<double>::max());
  check("peak_memory_kib", row.peak_memory_kib, false);
  // Words are checked as numbers are: `<script>` edited into image_verdict was shown by history as
  // the verdict (a sweep).
  const auto word = [&](const char* column, const std::string& value, bool known) {
    if (known) return;
    throw InfraError(fmt::format(
        "results store {}: document {}, scene {}: {} is '{}', a word no document holds; the store "
        "is damaged (rebuild it: raygate import its results documents into a new store)",
        location, row.document_id, row.scene_id, column, terminal_line(value.substr(0, 40))));
  };
  word("status", row.status, parse_scene_status(row.status).has_value());
  word("role", row.role, parse_role(row.role).has_value());
  word("image_verdict", row.image_verdict,
       row.image_verdict.empty() || parse_image_verdict(row.image_verdict).has_value());
  word("memory_verdict", row.memory_verdict,
       row.memory_verdict.empty() || change_verdict_named(row.memory_verdict).has_value());
}

nlohmann::json parse_stored_document(const std::string& text, std::int64_t id,
                                     const std::string& location) {
  try {
    return nlohmann::json::parse(repaired_utf8(text));
  } catch (const nlohmann::json::parse_error& e) {
    throw InfraError(
        fmt::format("results store {}: document {} is not JSON ({}); the store is damaged",
                    location, id, plain_exception_text(e)));
  }
}

}  // namespace raygate

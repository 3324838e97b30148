// What a backend writes for one results document, worked out once for every backend: the
// canonical JSON and its content hash (the identity that makes imports idempotent), and the
// normalized rows of the documents, revisions and scene_results tables (docs/store.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/utf8.h"
#include "results/results.h"
#include "store/store.h"

namespace raygate {

struct DocumentRow {
  std::string content_sha256;
  int schema_version = 0;
  std::string kind;
  std::string branch;
  std::string suite;
  std::string shard;
  bool complete = false;
  std::string started_at;
  std::string finished_at;
  std::string stored_at;
  std::string raygate_version;
  std::string baseline_version;
  std::string baseline_sha256;
  std::string machine_hostname;
  std::string machine_cpu_model;
  std::string timing;          // results/series.h timing_identity()
  std::string baseline_accel;  // with baseline_sha256, the baseline's identity
  std::string document_json;  // canonical: compact, keys sorted
};

struct RevisionRow {
  std::string role;
  std::string repository;
  std::string sha;
  std::string short_sha;
  std::string subject;
  std::string author;
  std::string ref_name;
  std::string commit_time;
  std::optional<std::int64_t> commit_unix;
  bool dirty = false;
  std::string adapter_name;
  std::string adapter_hash;
  std::string repository_key;  // results/series.h
};

// One scene as one revision (role) saw it. Numbers that are absent or not finite are nullopt.
struct SceneRow {
  std::string scene_id;
  std::string role;
  std::string status;
  std::int64_t rounds = 0;
  std::optional<double> ratio;
  std::optional<double> ratio_lower;
  std::optional<double> ratio_upper;
  std::optional<double> tracer_median_seconds;
  std::optional<double> baseline_median_seconds;
  std::string image_verdict;  // the check against the golden; "" when there was none
  std::optional<double> image_max_error;
  std::optional<double> image_rms_error;
  std::optional<double> change;  // compare, on the head row: head against base
  std::optional<double> change_lower;
  std::optional<double> change_upper;
  std::string change_verdict;
  std::string scene_settings;  // results/series.h
  std::string series_id;       // SeriesKey::id() of this scene as this revision measured it
};

struct DocumentRows {
  DocumentRow document;
  std::vector<RevisionRow> revisions;
  std::vector<SceneRow> scenes;  // per scene, one row per revision role
};

// to_json(document), compact with sorted keys: the same document always gives the same text.
std::string canonical_json(const ResultsDocument& document);

DocumentRows document_rows(const ResultsDocument& document, const std::string& branch,
                           const std::string& stored_at);

// The series columns (store migration 2) of a document stored before they existed, worked out
// from its stored text. `known` is false for a document that no longer reads back: its rows get
// unknown_series_id(id) (results/series.h).
struct StoredSeries {
  bool known = false;
  DocumentRows rows;  // the columns of document_rows(); the others are left as computed
};
StoredSeries stored_series(const std::string& document_json, std::int64_t id);

// "2026-11-21T06:31:50+00:00", "...Z", "...+0130", fractions ignored -> seconds since 1970 UTC.
std::optional<std::int64_t> parse_iso8601_unix(std::string_view text);

// "refs/heads/main" -> "main", "refs/remotes/origin/x" -> "origin/x", "refs/tags/v1" -> "v1".
std::string short_ref_name(const std::string& ref_name);

// A stored document's JSON text parsed back, invalid UTF-8 in it repaired first (as the text
// columns are); text that is not JSON means a damaged store (InfraError naming the store and
// the document id).
nlohmann::json parse_stored_document(const std::string& text, std::int64_t id,
                                     const std::string& location);

// The select list and joins of both backends' measurements() query, in the column order
// history_row_from() reads; each backend adds its own WHERE (their parameter syntax differs).
inline constexpr const char* kMeasurementsFrom = R"sql(
SELECT d.id, d.stored_at, d.started_at, d.complete, d.branch, r.role, r.sha, r.short_sha,
  r.subject, r.commit_time, r.commit_unix, r.dirty, s.scene_id, s.status, s.normalized_ratio,
  s.ratio_lower, s.ratio_upper, s.baseline_median_seconds, s.image_verdict, s.image_max_error,
  s.image_rms_error, d.machine_hostname, d.machine_cpu_model, d.baseline_sha256,
  r.repository_key, r.adapter_name, d.suite, s.scene_settings, d.timing, d.baseline_accel,
  s.series_id
FROM scene_results s
JOIN revisions r ON r.document_id = s.document_id AND r.role = s.role
JOIN documents d ON d.id = s.document_id
)sql";

// One measurements() row from the columns of the backends' shared query (its select list, in
// order), read through `columns`: text(c), integer(c), optional_integer(c), real(c), flag(c).
// Text columns are repaired to UTF-8 (core/utf8.h): a store written before text was repaired
// where it enters, or by hand, may hold invalid bytes, and JSON output of them would throw.
template <class Columns>
HistoryRow history_row_from(const Columns& columns) {
  const auto text = [&columns](int column) { return repaired_utf8(columns.text(column)); };
  HistoryRow row;
  row.document_id = columns.integer(0);
  row.stored_at = text(1);
  row.measured_at = text(2);
  row.complete = columns.flag(3);
  row.branch = text(4);
  row.role = text(5);
  row.sha = text(6);
  row.short_sha = text(7);
  row.subject = text(8);
  row.commit_time = text(9);
  row.commit_unix = columns.optional_integer(10);
  row.dirty = columns.flag(11);
  row.scene_id = text(12);
  row.status = text(13);
  row.ratio = columns.real(14);
  row.ratio_lower = columns.real(15);
  row.ratio_upper = columns.real(16);
  row.baseline_median_seconds = columns.real(17);
  row.image_verdict = text(18);
  row.image_max_error = columns.real(19);
  row.image_rms_error = columns.real(20);
  row.machine_hostname = text(21);
  row.machine_cpu_model = text(22);
  row.baseline_sha256 = text(23);
  row.repository_key = text(24);
  row.adapter_name = text(25);
  row.suite = text(26);
  row.scene_settings = text(27);
  row.timing = text(28);
  row.baseline_accel = text(29);
  row.series_id = text(30);
  return row;
}

}  // namespace raygate

// What the store writes for one results document, worked out once for both dialects: the
// canonical JSON and its content hash (the identity that makes imports idempotent), and the
// row records of the documents, revisions and scene_results tables (docs/store.md). Which field
// is stored in which column is said once, in the column tables of store/schema.h.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

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
  std::string document_json;   // canonical: compact, keys sorted
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
  // Peak resident memory (issue 27): the median of this revision's own peaks over the scene's
  // rounds (runs started through raygate-meter; none in documents from before it).
  std::optional<double> peak_memory_kib;
  // compare, on the head row: head's peak against base's, and its verdict under the limit the
  // document was measured with (settings.max_memory_increase; gate/memory_gate.h).
  std::optional<double> memory_change;
  std::string memory_verdict;
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

// The rows of a document stored before some of their columns existed (a migration that
// backfills, store/migrate.h), worked out from its stored text. `known` is false for a document
// that no longer reads back: its rows get unknown_series_id(id) (results/series.h).
struct StoredSeries {
  bool known = false;
  DocumentRows rows;  // the columns of document_rows(); the others are left as computed
};
StoredSeries stored_series(const std::string& document_json, std::int64_t id);

// "2026-11-21T06:31:50+00:00", "...Z", "...+0130", fractions ignored -> seconds since 1970 UTC.
std::optional<std::int64_t> parse_iso8601_unix(std::string_view text);

// "refs/heads/main" -> "main", "refs/remotes/origin/x" -> "origin/x", "refs/tags/v1" -> "v1".
std::string short_ref_name(const std::string& ref_name);

// A history row's numbers checked as import checks a document's (results_check.cpp): a ratio,
// its interval, a baseline time or a memory peak that is not above 0 and finite, an image error
// below 0, was written by hand into the file (sqlite3), and would change what history and
// alert say (a ratio of 0 hid a +50% regression, exit 0; a sweep). InfraError naming the
// store, the document, the scene and the column: the store is damaged.
void check_history_row(const HistoryRow& row, const std::string& location);

// A stored document's JSON text parsed back, invalid UTF-8 in it repaired first (as the text
// columns are); text that is not JSON means a damaged store (InfraError naming the store and
// the document id).
nlohmann::json parse_stored_document(const std::string& text, std::int64_t id,
                                     const std::string& location);

}  // namespace raygate

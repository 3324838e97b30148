// What a backend writes for one results document, worked out once for every backend: the
// canonical JSON and its content hash (the identity that makes imports idempotent), and the
// normalized rows of the documents, revisions and scene_results tables (docs/store.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "store/results.h"

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

// "2026-11-21T06:31:50+00:00", "...Z", "...+0130", fractions ignored -> seconds since 1970 UTC.
std::optional<std::int64_t> parse_iso8601_unix(std::string_view text);

// "refs/heads/main" -> "main", "refs/remotes/origin/x" -> "origin/x", "refs/tags/v1" -> "v1".
std::string short_ref_name(const std::string& ref_name);

}  // namespace raygate

// The results store (DESIGN.md §8): every results document raygate writes or imports, kept
// whole (so export gives it back byte for byte) and indexed by commit, branch, scene and machine
// for history, trends and drift checks. One interface, one SQL store (store/sql_store.h) over two
// dialects: an SQLite file (the embedded default) and a PostgreSQL database for teams (one
// schema, store/schema.h; docs/store.md). The store stores and filters; the choices made on rows
// (latest per commit, --last) live in store/history.h so every backend answers a query alike.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "results/results.h"

namespace raygate {

inline constexpr const char* kDefaultStorePath = ".raygate/results.db";

struct AddOutcome {
  std::int64_t document_id = 0;
  bool duplicate = false;  // the same content was stored before; nothing was written
};

// One stored document as it was added.
struct StoredDocument {
  std::int64_t id = 0;
  std::string stored_at;  // ISO-8601 UTC
  std::string branch;
  std::string content_sha256;  // of the canonical JSON (store/store_rows.h)
  nlohmann::json document;     // exactly what was stored
};

// Which documents: every filter set must match. Newest stored first.
struct DocumentQuery {
  std::string sha_prefix;  // any revision of the document whose sha starts with this
  std::string branch;
  std::size_t last = 0;  // at most this many (0: all)
};

// One (document, scene, role) measurement with the commit it measured.
struct HistoryRow {
  std::int64_t document_id = 0;
  std::string stored_at;    // when the store got it
  std::string measured_at;  // the document's started_at
  bool complete = true;     // the document covered every selected scene
  std::string branch;
  std::string role;  // "tracer", "base", "head"
  std::string sha;
  std::string short_sha;
  std::string subject;
  std::string commit_time;                  // ISO-8601 with offset; empty for uncommitted trees
  std::optional<std::int64_t> commit_unix;  // seconds since 1970, for ordering
  bool dirty = false;
  std::string scene_id;
  std::string status;           // "measured" or "failed"
  std::optional<double> ratio;  // normalized ratio time(tracer) / time(baseline)
  std::optional<double> ratio_lower;
  std::optional<double> ratio_upper;
  std::optional<double> baseline_median_seconds;
  std::string image_verdict;  // against the golden: pass, warn, fail, missing, error; "" none
  std::optional<double> image_max_error;
  std::optional<double> image_rms_error;
  // Peak resident memory, the median of this revision's own peaks (nullopt before raygate-meter);
  // a compare's head row also has its change against base and the memory verdict.
  std::optional<double> peak_memory_kib;
  std::optional<double> memory_change;
  std::string memory_verdict;  // UNCHANGED, REGRESSED, IMPROVED, INCONCLUSIVE; "" none
  std::string machine_hostname;
  std::string machine_cpu_model;
  std::string baseline_sha256;  // ratios compare only across the same baseline
  // The series (results/series.h): trends, drift and comparisons stay within one series_id.
  std::string repository_key;
  std::string adapter_name;
  std::string suite;
  std::string scene_settings;
  std::string timing;
  std::string baseline_accel;
  std::string series_id;
};

struct HistoryQuery {
  std::string branch;               // "" any
  std::vector<std::string> scenes;  // empty: all
  std::string role = "tracer";      // "any": every measured revision
  bool include_dirty = false;       // trees with local changes are not commits
  std::size_t last_commits = 0;     // history(): at most this many commits (0: all)
  std::string repository;           // "" any; else repository keys containing this text
  std::string adapter;              // "" any; else this adapter name
  std::string suite;                // "" any; else this suite
  std::string series;               // "" any; else series ids starting with this
};

class ResultsStore {
 public:
  virtual ~ResultsStore() = default;

  // Stores `document` in one transaction: all of it or, on any failure, nothing. `branch` is
  // recorded for history filters. A document whose canonical JSON is already stored is not
  // stored again (duplicate = true, its earlier id).
  virtual AddOutcome add(const ResultsDocument& document, const std::string& branch) = 0;

  virtual std::vector<StoredDocument> documents(const DocumentQuery& query) = 0;

  // Every stored measurement matching the filters (last_commits ignored), newest commit first;
  // the same commit and scene may appear once per document that measured it.
  virtual std::vector<HistoryRow> measurements(const HistoryQuery& query) = 0;

  // Where the store lives, for messages (a path; a URL without its password).
  virtual std::string location() const = 0;

  // One row per commit and series (the latest measurement of it), newest commit first, at most
  // query.last_commits commits.
  std::vector<HistoryRow> history(const HistoryQuery& query);
};

enum class StoreOpen {
  create_if_missing,  // run, import: a new store is made
  must_exist,         // history, export: a missing store is a UsageError saying how to fill one
};

// An SQLite file for a path; a "postgresql://" or "postgres://" URL connects to the team store
// (store/postgres_url.h: a malformed URL is a UsageError, a server that cannot be reached an
// InfraError). Migrates the schema to the newest version.
std::unique_ptr<ResultsStore> open_store(const std::string& location,
                                         StoreOpen mode = StoreOpen::create_if_missing);

// The branch a document is recorded under: the short name of the measured revision's ref
// ("refs/heads/main" -> "main"), else `fallback`.
std::string branch_of(const ResultsDocument& document, const std::string& fallback);

}  // namespace raygate

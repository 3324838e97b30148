// Writing documents into the SQLite store and reading them and their history rows back.
#include "store/sqlite_store.h"

#include <fmt/core.h>

#include "core/error.h"
#include "core/time_text.h"
#include "store/sqlite_schema.h"
#include "store/store_rows.h"

namespace raygate {

namespace {

SqliteDb open_database(const std::filesystem::path& path, StoreOpen mode,
                       std::chrono::milliseconds busy_timeout) {
  if (mode == StoreOpen::must_exist && !std::filesystem::exists(path)) {
    throw UsageError(
        fmt::format("results store {} does not exist; `raygate run` records into "
                    "it, `raygate import FILE...` fills it from documents",
                    path.string()));
  }
  std::error_code error;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), error);
  if (error) {
    throw InfraError(fmt::format("results store {}: cannot create its directory: {}", path.string(),
                                 error.message()));
  }
  return SqliteDb::open(path, mode == StoreOpen::create_if_missing, busy_timeout);
}

const char* const kInsertDocument = R"sql(
INSERT INTO documents (content_sha256, schema_version, kind, branch, suite, shard, complete,
  started_at, finished_at, stored_at, raygate_version, baseline_version, baseline_sha256,
  machine_hostname, machine_cpu_model, document_json, timing, baseline_accel)
VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18))sql";

const char* const kInsertRevision = R"sql(
INSERT INTO revisions (document_id, role, repository, sha, short_sha, subject, author, ref_name,
  commit_time, commit_unix, dirty, adapter_name, adapter_hash, repository_key)
VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14))sql";

const char* const kInsertScene = R"sql(
INSERT INTO scene_results (document_id, scene_id, role, status, rounds, normalized_ratio,
  ratio_lower, ratio_upper, tracer_median_seconds, baseline_median_seconds, image_verdict,
  image_max_error, image_rms_error, relative_change, change_lower, change_upper, change_verdict,
  scene_settings, series_id)
VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18, ?19))sql";

const char* const kSelectDocuments = R"sql(
SELECT d.id, d.stored_at, d.branch, d.content_sha256, d.document_json FROM documents d
WHERE (?1 = '' OR d.branch = ?1)
  AND (?2 = '' OR EXISTS (SELECT 1 FROM revisions r
                          WHERE r.document_id = d.id AND substr(r.sha, 1, length(?2)) = ?2))
ORDER BY d.id DESC LIMIT ?3)sql";

// After kMeasurementsFrom (store_rows.h).
const char* const kMeasurementsWhere = R"sql(
WHERE (?1 = '' OR d.branch = ?1) AND (?2 = 'any' OR s.role = ?2) AND (?3 = 1 OR r.dirty = 0)
  AND (?4 = '' OR instr(r.repository_key, ?4) > 0) AND (?5 = '' OR r.adapter_name = ?5)
  AND (?6 = '' OR d.suite = ?6) AND (?7 = '' OR substr(s.series_id, 1, length(?7)) = ?7))sql";

constexpr std::size_t kFixedParameters = 7;  // of kMeasurementsWhere

const char* const kMeasurementOrder =
    " ORDER BY r.commit_unix DESC NULLS LAST, d.started_at DESC, d.id DESC, s.scene_id";

// " AND s.scene_id IN (?8, ?9, ...)" for the scenes asked for, numbered after the fixed seven.
std::string scene_filter(const std::vector<std::string>& scenes) {
  if (scenes.empty()) return {};
  std::string sql = " AND s.scene_id IN (";
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    sql += fmt::format("{}?{}", i == 0 ? "" : ", ", i + kFixedParameters + 1);
  }
  return sql + ")";
}

// The history columns of the current row.
struct StatementColumns {
  const SqliteStatement& statement;
  std::string text(int c) const { return statement.text(c); }
  std::int64_t integer(int c) const { return statement.integer(c); }
  std::optional<std::int64_t> optional_integer(int c) const {
    return statement.optional_integer(c);
  }
  std::optional<double> real(int c) const { return statement.real(c); }
  bool flag(int c) const { return statement.integer(c) != 0; }
};

}  // namespace

SqliteStore::SqliteStore(const std::filesystem::path& path, StoreOpen mode,
                         std::chrono::milliseconds busy_timeout)
    : db_(open_database(path, mode, busy_timeout)) {
  configure_connection(db_);
  migrate(db_, sqlite_migrations());
}

AddOutcome SqliteStore::add(const ResultsDocument& document, const std::string& branch) {
  const DocumentRows rows = document_rows(document, branch, utc_timestamp());
  SqliteTransaction transaction(db_);
  if (const auto existing = find_document(rows.document.content_sha256)) {
    return {*existing, true};
  }
  const std::int64_t id = insert_document(rows.document);
  for (const RevisionRow& revision : rows.revisions) insert_revision(id, revision);
  for (const SceneRow& scene : rows.scenes) insert_scene(id, scene);
  transaction.commit();
  return {id, false};
}

std::optional<std::int64_t> SqliteStore::find_document(const std::string& content_sha256) {
  SqliteStatement find(db_, "SELECT id FROM documents WHERE content_sha256 = ?1");
  find.bind_text(1, content_sha256);
  if (!find.step()) return std::nullopt;
  return find.integer(0);
}

std::int64_t SqliteStore::insert_document(const DocumentRow& row) {
  SqliteStatement s(db_, kInsertDocument);
  s.bind_text(1, row.content_sha256).bind_int(2, row.schema_version).bind_text(3, row.kind);
  s.bind_text(4, row.branch).bind_text(5, row.suite).bind_text(6, row.shard);
  s.bind_flag(7, row.complete).bind_text(8, row.started_at).bind_text(9, row.finished_at);
  s.bind_text(10, row.stored_at).bind_text(11, row.raygate_version);
  s.bind_text(12, row.baseline_version).bind_text(13, row.baseline_sha256);
  s.bind_text(14, row.machine_hostname).bind_text(15, row.machine_cpu_model);
  s.bind_text(16, row.document_json).bind_text(17, row.timing);
  s.bind_text(18, row.baseline_accel);
  s.run();
  SqliteStatement id(db_, "SELECT last_insert_rowid()");
  id.step();
  return id.integer(0);
}

void SqliteStore::insert_revision(std::int64_t document_id, const RevisionRow& row) {
  SqliteStatement s(db_, kInsertRevision);
  s.bind_int(1, document_id).bind_text(2, row.role).bind_text(3, row.repository);
  s.bind_text(4, row.sha).bind_text(5, row.short_sha).bind_text(6, row.subject);
  s.bind_text(7, row.author).bind_text(8, row.ref_name).bind_text(9, row.commit_time);
  s.bind_int(10, row.commit_unix).bind_flag(11, row.dirty).bind_text(12, row.adapter_name);
  s.bind_text(13, row.adapter_hash).bind_text(14, row.repository_key);
  s.run();
}

void SqliteStore::insert_scene(std::int64_t document_id, const SceneRow& row) {
  SqliteStatement s(db_, kInsertScene);
  s.bind_int(1, document_id).bind_text(2, row.scene_id).bind_text(3, row.role);
  s.bind_text(4, row.status).bind_int(5, row.rounds).bind_real(6, row.ratio);
  s.bind_real(7, row.ratio_lower).bind_real(8, row.ratio_upper);
  s.bind_real(9, row.tracer_median_seconds).bind_real(10, row.baseline_median_seconds);
  s.bind_text(11, row.image_verdict).bind_real(12, row.image_max_error);
  s.bind_real(13, row.image_rms_error).bind_real(14, row.change);
  s.bind_real(15, row.change_lower).bind_real(16, row.change_upper);
  s.bind_text(17, row.change_verdict).bind_text(18, row.scene_settings);
  s.bind_text(19, row.series_id);
  s.run();
}

std::vector<StoredDocument> SqliteStore::documents(const DocumentQuery& query) {
  SqliteStatement s(db_, kSelectDocuments);
  s.bind_text(1, query.branch).bind_text(2, query.sha_prefix);
  s.bind_int(3, query.last == 0 ? -1 : static_cast<std::int64_t>(query.last));
  std::vector<StoredDocument> out;
  while (s.step()) {
    StoredDocument d;
    d.id = s.integer(0);
    d.stored_at = s.text(1);
    d.branch = repaired_utf8(s.text(2));
    d.content_sha256 = s.text(3);
    d.document = parse_stored_document(s.text(4), d.id, location());
    out.push_back(std::move(d));
  }
  return out;
}

std::vector<HistoryRow> SqliteStore::measurements(const HistoryQuery& query) {
  SqliteStatement s(db_, kMeasurementsFrom + std::string(kMeasurementsWhere) +
                             scene_filter(query.scenes) + kMeasurementOrder);
  s.bind_text(1, query.branch).bind_text(2, query.role).bind_flag(3, query.include_dirty);
  s.bind_text(4, query.repository).bind_text(5, query.adapter).bind_text(6, query.suite);
  s.bind_text(7, query.series);
  for (std::size_t i = 0; i < query.scenes.size(); ++i) {
    s.bind_text(static_cast<int>(i + kFixedParameters + 1), query.scenes[i]);
  }
  std::vector<HistoryRow> rows;
  while (s.step()) rows.push_back(history_row_from(StatementColumns{s}));
  return rows;
}

}  // namespace raygate

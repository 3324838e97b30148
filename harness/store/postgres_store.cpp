// Writing documents into the PostgreSQL store and reading them and their history rows back.
// The queries are the SQLite store's (store/sqlite_store.cpp) in PostgreSQL's dialect, so both
// backends filter and order alike: text is ordered bytewise (COLLATE "C", SQLite's BINARY)
// whatever the database's locale.
#include "store/postgres_store.h"

#include <fmt/core.h>

#include "core/error.h"
#include "core/time_text.h"
#include "store/postgres_schema.h"
#include "store/store_rows.h"

namespace raygate {

namespace {

// Another writer may have stored the same content a moment earlier: its row stands, this
// insert returns no id and writes nothing (the UNIQUE key on content_sha256 decides).
const char* const kInsertDocument = R"sql(
INSERT INTO documents (content_sha256, schema_version, kind, branch, suite, shard, complete,
  started_at, finished_at, stored_at, raygate_version, baseline_version, baseline_sha256,
  machine_hostname, machine_cpu_model, document_json, timing, baseline_accel)
VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14, $15, $16, $17, $18)
ON CONFLICT (content_sha256) DO NOTHING
RETURNING id)sql";

const char* const kInsertRevision = R"sql(
INSERT INTO revisions (document_id, role, repository, sha, short_sha, subject, author, ref_name,
  commit_time, commit_unix, dirty, adapter_name, adapter_hash, repository_key)
VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14))sql";

const char* const kInsertScene = R"sql(
INSERT INTO scene_results (document_id, scene_id, role, status, rounds, normalized_ratio,
  ratio_lower, ratio_upper, tracer_median_seconds, baseline_median_seconds, image_verdict,
  image_max_error, image_rms_error, relative_change, change_lower, change_upper, change_verdict,
  scene_settings, series_id)
VALUES ($1, $2, $3, $4, $5, $6, $7, $8, $9, $10, $11, $12, $13, $14, $15, $16, $17, $18, $19))sql";

// LIMIT NULL is no limit.
const char* const kSelectDocuments = R"sql(
SELECT d.id, d.stored_at, d.branch, d.content_sha256, d.document_json FROM documents d
WHERE ($1::text = '' OR d.branch = $1::text)
  AND ($2::text = '' OR EXISTS (SELECT 1 FROM revisions r WHERE r.document_id = d.id
                                AND substr(r.sha, 1, length($2::text)) = $2::text))
ORDER BY d.id DESC LIMIT $3::bigint)sql";

// After kMeasurementsFrom (store_rows.h).
const char* const kMeasurementsWhere = R"sql(
WHERE ($1::text = '' OR d.branch = $1::text) AND ($2::text = 'any' OR s.role = $2::text)
  AND ($3::boolean OR NOT r.dirty)
  AND ($4::text = '' OR strpos(r.repository_key, $4::text) > 0)
  AND ($5::text = '' OR r.adapter_name = $5::text) AND ($6::text = '' OR d.suite = $6::text)
  AND ($7::text = '' OR substr(s.series_id, 1, length($7::text)) = $7::text))sql";

const char* const kMeasurementOrder =
    " ORDER BY r.commit_unix DESC NULLS LAST, d.started_at COLLATE \"C\" DESC, d.id DESC,"
    " s.scene_id COLLATE \"C\"";

// " AND s.scene_id IN ($8, $9, ...)" for the scenes asked for, numbered after the fixed seven:
// placeholders only, the scene ids travel as parameters.
std::string scene_filter(const std::vector<std::string>& scenes) {
  if (scenes.empty()) return {};
  std::string sql = " AND s.scene_id IN (";
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    sql += fmt::format("{}${}::text", i == 0 ? "" : ", ", i + 8);
  }
  return sql + ")";
}

// The history columns of one result row.
struct ResultColumns {
  const PgResult& result;
  int row;
  std::string text(int c) const { return result.text(row, c); }
  std::int64_t integer(int c) const { return result.integer(row, c); }
  std::optional<std::int64_t> optional_integer(int c) const {
    return result.optional_integer(row, c);
  }
  std::optional<double> real(int c) const { return result.real(row, c); }
  bool flag(int c) const { return result.flag(row, c); }
};

}  // namespace

PostgresStore::PostgresStore(const std::string& url, StoreOpen mode)
    : db_(PgConnection::connect(url)) {
  if (mode == StoreOpen::must_exist && schema_version(db_) == 0) {
    throw UsageError(
        fmt::format("results store {} has no raygate tables yet; `raygate run --store URL` "
                    "records into it, `raygate import FILE... --store URL` fills it",
                    db_.location()));
  }
  migrate(db_, postgres_migrations());
}

AddOutcome PostgresStore::add(const ResultsDocument& document, const std::string& branch) {
  const DocumentRows rows = document_rows(document, branch, utc_timestamp());
  // Checked first so that re-importing stored documents uses up no ids.
  if (const auto existing = find_document(rows.document.content_sha256)) return {*existing, true};
  {
    PgTransaction transaction(db_);
    if (const std::optional<std::int64_t> id = insert_document(rows.document)) {
      for (const RevisionRow& revision : rows.revisions) insert_revision(*id, revision);
      for (const SceneRow& scene : rows.scenes) insert_scene(*id, scene);
      transaction.commit();
      return {*id, false};
    }
  }  // nothing was written; rolled back
  // Another writer committed the same content while this insert waited on the unique key.
  if (const auto existing = find_document(rows.document.content_sha256)) return {*existing, true};
  throw InfraError(fmt::format(
      "results store {}: document {} was neither stored nor found (a concurrent writer's "
      "row vanished); retry",
      location(), rows.document.content_sha256));
}

std::optional<std::int64_t> PostgresStore::find_document(const std::string& content_sha256) {
  const PgResult found = db_.exec("SELECT id FROM documents WHERE content_sha256 = $1",
                                  PgParams().text(content_sha256));
  if (found.rows() == 0) return std::nullopt;
  return found.integer(0, 0);
}

std::optional<std::int64_t> PostgresStore::insert_document(const DocumentRow& row) {
  PgParams p;
  p.text(row.content_sha256).integer(row.schema_version).text(row.kind).text(row.branch);
  p.text(row.suite).text(row.shard).flag(row.complete).text(row.started_at);
  p.text(row.finished_at).text(row.stored_at).text(row.raygate_version);
  p.text(row.baseline_version).text(row.baseline_sha256).text(row.machine_hostname);
  p.text(row.machine_cpu_model).text(row.document_json).text(row.timing);
  p.text(row.baseline_accel);
  const PgResult inserted = db_.exec(kInsertDocument, p);
  if (inserted.rows() == 0) return std::nullopt;
  return inserted.integer(0, 0);
}

void PostgresStore::insert_revision(std::int64_t document_id, const RevisionRow& row) {
  PgParams p;
  p.integer(document_id).text(row.role).text(row.repository).text(row.sha);
  p.text(row.short_sha).text(row.subject).text(row.author).text(row.ref_name);
  p.text(row.commit_time).integer(row.commit_unix).flag(row.dirty).text(row.adapter_name);
  p.text(row.adapter_hash).text(row.repository_key);
  db_.exec(kInsertRevision, p);
}

void PostgresStore::insert_scene(std::int64_t document_id, const SceneRow& row) {
  PgParams p;
  p.integer(document_id).text(row.scene_id).text(row.role).text(row.status);
  p.integer(row.rounds).real(row.ratio).real(row.ratio_lower).real(row.ratio_upper);
  p.real(row.tracer_median_seconds).real(row.baseline_median_seconds);
  p.text(row.image_verdict).real(row.image_max_error).real(row.image_rms_error);
  p.real(row.change).real(row.change_lower).real(row.change_upper).text(row.change_verdict);
  p.text(row.scene_settings).text(row.series_id);
  db_.exec(kInsertScene, p);
}

std::vector<StoredDocument> PostgresStore::documents(const DocumentQuery& query) {
  PgParams p;
  p.text(query.branch).text(query.sha_prefix);
  p.integer(query.last == 0 ? std::nullopt
                            : std::optional<std::int64_t>(static_cast<std::int64_t>(query.last)));
  const PgResult r = db_.exec(kSelectDocuments, p);
  std::vector<StoredDocument> out;
  for (int i = 0; i < r.rows(); ++i) {
    StoredDocument d;
    d.id = r.integer(i, 0);
    d.stored_at = r.text(i, 1);
    d.branch = repaired_utf8(r.text(i, 2));
    d.content_sha256 = r.text(i, 3);
    d.document = parse_stored_document(r.text(i, 4), d.id, location());
    out.push_back(std::move(d));
  }
  return out;
}

std::vector<HistoryRow> PostgresStore::measurements(const HistoryQuery& query) {
  PgParams p;
  p.text(query.branch).text(query.role).flag(query.include_dirty);
  p.text(query.repository).text(query.adapter).text(query.suite).text(query.series);
  for (const std::string& scene : query.scenes) p.text(scene);
  const PgResult r =
      db_.exec(kMeasurementsFrom + std::string(kMeasurementsWhere) +
                   scene_filter(query.scenes) + kMeasurementOrder,
               p);
  std::vector<HistoryRow> rows;
  for (int i = 0; i < r.rows(); ++i) rows.push_back(history_row_from(ResultColumns{r, i}));
  return rows;
}

}  // namespace raygate

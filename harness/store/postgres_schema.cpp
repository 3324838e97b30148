// Migrations of the PostgreSQL store.
#include "store/postgres_schema.h"

#include <fmt/core.h>

#include <vector>

#include "core/error.h"
#include "core/time_text.h"
#include "results/series.h"
#include "store/store_rows.h"

namespace raygate {

namespace {

// Migration 1: SQLite's migration 1 column for column. INTEGER keys are BIGINT (SQLite's are
// 64-bit), REAL is DOUBLE PRECISION, 0/1 flags are BOOLEAN. document_json is TEXT, not JSONB:
// JSONB would reorder keys and rewrite numbers, and export must give the stored text back
// exactly (ad-hoc queries can still say document_json::jsonb).
const char* const kCreateTables = R"sql(
CREATE TABLE documents (
  id                BIGSERIAL PRIMARY KEY,
  content_sha256    TEXT    NOT NULL UNIQUE,
  schema_version    INTEGER NOT NULL,
  kind              TEXT    NOT NULL,
  branch            TEXT    NOT NULL,
  suite             TEXT    NOT NULL,
  shard             TEXT    NOT NULL,
  complete          BOOLEAN NOT NULL,
  started_at        TEXT    NOT NULL,
  finished_at       TEXT    NOT NULL,
  stored_at         TEXT    NOT NULL,
  raygate_version   TEXT    NOT NULL,
  baseline_version  TEXT    NOT NULL,
  baseline_sha256   TEXT    NOT NULL,
  machine_hostname  TEXT    NOT NULL,
  machine_cpu_model TEXT    NOT NULL,
  document_json     TEXT    NOT NULL
);
CREATE TABLE revisions (
  document_id  BIGINT  NOT NULL REFERENCES documents(id) ON DELETE CASCADE,
  role         TEXT    NOT NULL,
  repository   TEXT    NOT NULL,
  sha          TEXT    NOT NULL,
  short_sha    TEXT    NOT NULL,
  subject      TEXT    NOT NULL,
  author       TEXT    NOT NULL,
  ref_name     TEXT    NOT NULL,
  commit_time  TEXT    NOT NULL,
  commit_unix  BIGINT,
  dirty        BOOLEAN NOT NULL,
  adapter_name TEXT    NOT NULL,
  adapter_hash TEXT    NOT NULL,
  PRIMARY KEY (document_id, role)
);
CREATE TABLE scene_results (
  document_id             BIGINT NOT NULL,
  scene_id                TEXT   NOT NULL,
  role                    TEXT   NOT NULL,
  status                  TEXT   NOT NULL,
  rounds                  BIGINT NOT NULL,
  normalized_ratio        DOUBLE PRECISION,
  ratio_lower             DOUBLE PRECISION,
  ratio_upper             DOUBLE PRECISION,
  tracer_median_seconds   DOUBLE PRECISION,
  baseline_median_seconds DOUBLE PRECISION,
  image_verdict           TEXT   NOT NULL,
  image_max_error         DOUBLE PRECISION,
  image_rms_error         DOUBLE PRECISION,
  relative_change         DOUBLE PRECISION,
  change_lower            DOUBLE PRECISION,
  change_upper            DOUBLE PRECISION,
  change_verdict          TEXT   NOT NULL,
  PRIMARY KEY (document_id, scene_id, role),
  FOREIGN KEY (document_id, role) REFERENCES revisions(document_id, role) ON DELETE CASCADE
);
CREATE INDEX documents_branch ON documents(branch, id);
CREATE INDEX documents_machine ON documents(machine_hostname, machine_cpu_model);
CREATE INDEX revisions_sha ON revisions(sha);
CREATE INDEX revisions_commit ON revisions(role, commit_unix);
CREATE INDEX scene_results_scene ON scene_results(scene_id, role);
)sql";

const std::vector<Migration> kMigrations = {
    {1, "documents, revisions, scene_results", kCreateTables},
    {2, kSeriesColumnsDescription, kSeriesColumnsSql, true},
};

void mark_unknown(PgConnection& db, std::int64_t id) {
  db.exec("UPDATE scene_results SET series_id = $2 WHERE document_id = $1",
          PgParams().integer(id).text(unknown_series_id(id)));
  db.exec("UPDATE revisions SET repository_key = 'unknown' WHERE document_id = $1",
          PgParams().integer(id));
}

void write_series(PgConnection& db, std::int64_t id, const DocumentRows& rows) {
  db.exec("UPDATE documents SET timing = $2, baseline_accel = $3 WHERE id = $1",
          PgParams().integer(id).text(rows.document.timing).text(rows.document.baseline_accel));
  for (const RevisionRow& r : rows.revisions) {
    db.exec("UPDATE revisions SET repository_key = $3 WHERE document_id = $1 AND role = $2",
            PgParams().integer(id).text(r.role).text(r.repository_key));
  }
  for (const SceneRow& r : rows.scenes) {
    PgParams p;
    p.integer(id).text(r.scene_id).text(r.role).text(r.scene_settings).text(r.series_id);
    db.exec("UPDATE scene_results SET scene_settings = $4, series_id = $5 "
            "WHERE document_id = $1 AND scene_id = $2 AND role = $3",
            p);
  }
}

// Every stored document, one at a time (a large store need not fit in memory).
void backfill_series(PgConnection& db) {
  const PgResult ids = db.exec("SELECT id FROM documents ORDER BY id");
  for (int i = 0; i < ids.rows(); ++i) {
    const std::int64_t id = ids.integer(i, 0);
    const PgResult text =
        db.exec("SELECT document_json FROM documents WHERE id = $1", PgParams().integer(id));
    const StoredSeries series = stored_series(text.text(0, 0), id);
    if (series.known) {
      write_series(db, id, series.rows);
    } else {
      mark_unknown(db, id);
    }
  }
}

// One migration with its bookkeeping, in one transaction. The advisory lock makes processes
// that open a fresh database at once take turns (CREATE TABLE IF NOT EXISTS alone races on the
// catalog); the version is read again under it, so the second one finds the work done.
void apply(PgConnection& db, const Migration& migration) {
  PgTransaction transaction(db);
  db.exec("SELECT pg_advisory_xact_lock($1)", PgParams().integer(kMigrationLockKey));
  db.exec(kMigrationsTableSql);
  if (schema_version(db) >= migration.version) return;
  db.exec_script(migration.sql);
  if (migration.backfills_series) backfill_series(db);
  db.exec("INSERT INTO schema_migrations (version, description, applied_at) VALUES ($1, $2, $3)",
          PgParams().integer(migration.version).text(migration.description).text(utc_timestamp()));
  transaction.commit();
}

}  // namespace

std::span<const Migration> postgres_migrations() { return kMigrations; }

int schema_version(PgConnection& db) {
  if (!db.exec("SELECT to_regclass('schema_migrations') IS NOT NULL").flag(0, 0)) return 0;
  return static_cast<int>(
      db.exec("SELECT coalesce(max(version), 0) FROM schema_migrations").integer(0, 0));
}

int migrate(PgConnection& db, std::span<const Migration> migrations) {
  const int known = migrations.empty() ? 0 : migrations.back().version;
  const int found = schema_version(db);
  if (found > known) {
    throw UsageError(
        fmt::format("results store {}: schema version {} is newer than this raygate "
                    "knows ({}); use a newer raygate",
                    db.location(), found, known));
  }
  for (const Migration& migration : migrations) {
    if (migration.version > found) apply(db, migration);
  }
  return schema_version(db);
}

}  // namespace raygate

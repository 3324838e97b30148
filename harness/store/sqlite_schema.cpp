// Migrations of the SQLite store and the connection settings that go with them.
#include "store/sqlite_schema.h"

#include <fmt/core.h>
#include <sqlite3.h>

#include <thread>
#include <vector>

#include "core/error.h"
#include "core/time_text.h"
#include "results/series.h"
#include "store/store_rows.h"

namespace raygate {

namespace {

// Migration 1: documents whole (document_json) plus the columns history queries use. Types are
// those PostgreSQL has too (INTEGER, REAL as DOUBLE PRECISION, TEXT); booleans are 0/1.
const char* const kCreateTables = R"sql(
CREATE TABLE documents (
  id                INTEGER PRIMARY KEY,
  content_sha256    TEXT    NOT NULL UNIQUE,
  schema_version    INTEGER NOT NULL,
  kind              TEXT    NOT NULL,
  branch            TEXT    NOT NULL,
  suite             TEXT    NOT NULL,
  shard             TEXT    NOT NULL,
  complete          INTEGER NOT NULL,
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
  document_id  INTEGER NOT NULL REFERENCES documents(id) ON DELETE CASCADE,
  role         TEXT    NOT NULL,
  repository   TEXT    NOT NULL,
  sha          TEXT    NOT NULL,
  short_sha    TEXT    NOT NULL,
  subject      TEXT    NOT NULL,
  author       TEXT    NOT NULL,
  ref_name     TEXT    NOT NULL,
  commit_time  TEXT    NOT NULL,
  commit_unix  INTEGER,
  dirty        INTEGER NOT NULL,
  adapter_name TEXT    NOT NULL,
  adapter_hash TEXT    NOT NULL,
  PRIMARY KEY (document_id, role)
);
CREATE TABLE scene_results (
  document_id             INTEGER NOT NULL,
  scene_id                TEXT    NOT NULL,
  role                    TEXT    NOT NULL,
  status                  TEXT    NOT NULL,
  rounds                  INTEGER NOT NULL,
  normalized_ratio        REAL,
  ratio_lower             REAL,
  ratio_upper             REAL,
  tracer_median_seconds   REAL,
  baseline_median_seconds REAL,
  image_verdict           TEXT    NOT NULL,
  image_max_error         REAL,
  image_rms_error         REAL,
  relative_change         REAL,
  change_lower            REAL,
  change_upper            REAL,
  change_verdict          TEXT    NOT NULL,
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

std::string document_text(SqliteDb& db, std::int64_t id) {
  SqliteStatement get(db, "SELECT document_json FROM documents WHERE id = ?1");
  get.bind_int(1, id);
  get.step();
  return get.text(0);
}

void mark_unknown(SqliteDb& db, std::int64_t id) {
  SqliteStatement scenes(db, "UPDATE scene_results SET series_id = ?2 WHERE document_id = ?1");
  scenes.bind_int(1, id).bind_text(2, unknown_series_id(id)).run();
  SqliteStatement revisions(db,
                            "UPDATE revisions SET repository_key = 'unknown' WHERE document_id = ?1");
  revisions.bind_int(1, id).run();
}

void write_series(SqliteDb& db, std::int64_t id, const DocumentRows& rows) {
  SqliteStatement document(db, "UPDATE documents SET timing = ?2, baseline_accel = ?3 WHERE id = ?1");
  document.bind_int(1, id).bind_text(2, rows.document.timing);
  document.bind_text(3, rows.document.baseline_accel).run();
  for (const RevisionRow& r : rows.revisions) {
    SqliteStatement revision(
        db, "UPDATE revisions SET repository_key = ?3 WHERE document_id = ?1 AND role = ?2");
    revision.bind_int(1, id).bind_text(2, r.role).bind_text(3, r.repository_key).run();
  }
  for (const SceneRow& r : rows.scenes) {
    SqliteStatement scene(db,
                          "UPDATE scene_results SET scene_settings = ?4, series_id = ?5 "
                          "WHERE document_id = ?1 AND scene_id = ?2 AND role = ?3");
    scene.bind_int(1, id).bind_text(2, r.scene_id).bind_text(3, r.role);
    scene.bind_text(4, r.scene_settings).bind_text(5, r.series_id).run();
  }
}

// Every stored document, one at a time (a large store need not fit in memory).
void backfill_series(SqliteDb& db) {
  std::vector<std::int64_t> ids;
  SqliteStatement list(db, "SELECT id FROM documents ORDER BY id");
  while (list.step()) ids.push_back(list.integer(0));
  for (const std::int64_t id : ids) {
    const StoredSeries series = stored_series(document_text(db, id), id);
    if (series.known) {
      write_series(db, id, series.rows);
    } else {
      mark_unknown(db, id);
    }
  }
}

// One migration with its bookkeeping, in one transaction; skipped if another process applied
// it first (the version is read again under the write lock).
void apply(SqliteDb& db, const Migration& migration) {
  SqliteTransaction transaction(db);
  if (schema_version(db) >= migration.version) return;
  db.exec(kMigrationsTableSql);
  db.exec(migration.sql);
  if (migration.backfills_series) backfill_series(db);
  SqliteStatement record(db,
                         "INSERT INTO schema_migrations (version, description, applied_at) "
                         "VALUES (?1, ?2, ?3)");
  record.bind_int(1, migration.version).bind_text(2, migration.description);
  record.bind_text(3, utc_timestamp()).run();
  db.exec(fmt::format("PRAGMA user_version = {}", migration.version));
  transaction.commit();
}

// Switching to WAL takes an exclusive lock that the busy handler does not always wait for
// (a fresh file opened by several processes at once): retry until the busy timeout.
void enable_wal(SqliteDb& db) {
  const auto deadline = std::chrono::steady_clock::now() + db.busy_timeout();
  for (;;) {
    const int code = sqlite3_exec(db.get(), "PRAGMA journal_mode = WAL", nullptr, nullptr, nullptr);
    if (code == SQLITE_OK) return;
    const bool busy = (code & 0xff) == SQLITE_BUSY || (code & 0xff) == SQLITE_LOCKED;
    if (!busy || std::chrono::steady_clock::now() > deadline) {
      db.fail(code, "PRAGMA journal_mode = WAL");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

}  // namespace

std::span<const Migration> sqlite_migrations() { return kMigrations; }

int schema_version(SqliteDb& db) {
  SqliteStatement statement(db, "PRAGMA user_version");
  statement.step();
  return static_cast<int>(statement.integer(0));
}

int migrate(SqliteDb& db, std::span<const Migration> migrations) {
  const int known = migrations.empty() ? 0 : migrations.back().version;
  const int found = schema_version(db);
  if (found > known) {
    throw UsageError(
        fmt::format("results store {}: schema version {} is newer than this raygate "
                    "knows ({}); use a newer raygate",
                    db.path().string(), found, known));
  }
  for (const Migration& migration : migrations) {
    if (migration.version > found) apply(db, migration);
  }
  return schema_version(db);
}

void configure_connection(SqliteDb& db) {
  enable_wal(db);
  db.exec("PRAGMA synchronous = FULL");
  db.exec("PRAGMA foreign_keys = ON");
}

}  // namespace raygate

// Migrations of the store, written once over the dialect layer.
#include "store/migrate.h"

#include <fmt/core.h>

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "core/time_text.h"
#include "results/series.h"
#include "store/row_values.h"
#include "store/store_rows.h"

namespace raygate {

namespace {

// One row per migration applied; the same SQL in both dialects.
constexpr const char* kMigrationsTableSql =
    "CREATE TABLE IF NOT EXISTS schema_migrations (version INTEGER PRIMARY KEY, "
    "description TEXT NOT NULL, applied_at TEXT NOT NULL)";

// The migration that creates a table: the one of its oldest column.
int created_by(const TableShape& table) {
  int version = -1;
  for (const Column& c : store_columns()) {
    if (c.table() == table.table && (version < 0 || c.since < version)) version = c.since;
  }
  return version;
}

std::string column_sql(const SqlDatabase& db, const Column& column) {
  return std::string(column.name) + " " + db.type_name(column.type()) +
         (column.nullable() ? "" : " NOT NULL");
}

std::string create_table_sql(const SqlDatabase& db, const TableShape& table, int version) {
  std::vector<std::string> parts;
  parts.push_back(table.child ? "document_id " + db.type_name(SqlType::int64) + " NOT NULL"
                              : "id " + db.identity_key());
  for (const Column& c : store_columns()) {
    if (c.table() == table.table && c.since <= version) parts.push_back(column_sql(db, c));
  }
  if (table.child) {
    std::string key = "document_id";
    for (const std::string& name : table.key) key += ", " + name;
    parts.push_back("PRIMARY KEY (" + key + ")");
  }
  parts.insert(parts.end(), table.constraints.begin(), table.constraints.end());
  std::string sql = "CREATE TABLE " + table.name + " (";
  for (std::size_t i = 0; i < parts.size(); ++i) sql += (i == 0 ? "\n  " : ",\n  ") + parts[i];
  return sql + "\n);\n";
}

// A column added to a table that may hold rows: NOT NULL ones need a default for those rows.
std::string add_column_sql(const SqlDatabase& db, const TableShape& table, const Column& c) {
  constexpr const char* kZero[] = {"0", "0", "0", "''", "FALSE"};  // by SqlType, in order
  std::string sql = "ALTER TABLE " + table.name + " ADD COLUMN " + column_sql(db, c);
  if (!c.nullable()) sql += std::string(" DEFAULT ") + kZero[static_cast<int>(c.type())];
  return sql + ";\n";
}

// The tables and columns migration `version` brings, as one script.
std::string schema_sql(const SqlDatabase& db, int version) {
  std::string sql;
  for (const TableShape& table : store_tables()) {
    const int created = created_by(table);
    if (created == version) sql += create_table_sql(db, table, version);
    if (created >= version) continue;
    for (const Column& c : store_columns()) {
      if (c.table() == table.table && c.since == version) sql += add_column_sql(db, table, c);
    }
  }
  return sql;
}

bool blank(const std::string& sql) {
  return std::all_of(sql.begin(), sql.end(), [](unsigned char c) { return std::isspace(c); });
}

// The series of a document that no longer reads back: one of its own, never joined to another.
void mark_unreadable(SqlDatabase& db, std::int64_t id) {
  const std::string p1 = db.parameter(1, SqlType::int64);
  db.query("UPDATE scene_results SET series_id = " + db.parameter(2, SqlType::text) +
               " WHERE document_id = " + p1,
           SqlParams().integer(id).text(unknown_series_id(id)), {});
  db.query("UPDATE revisions SET repository_key = 'unknown' WHERE document_id = " + p1,
           SqlParams().integer(id), {});
}

void fill_added(SqlDatabase& db, int version, std::int64_t id, const DocumentRows& rows) {
  update_added(db, store_table(StoreTable::documents), version, id, rows.document);
  const TableShape& revisions = store_table(StoreTable::revisions);
  for (const RevisionRow& r : rows.revisions) update_added(db, revisions, version, id, r);
  const TableShape& scenes = store_table(StoreTable::scene_results);
  for (const SceneRow& s : rows.scenes) update_added(db, scenes, version, id, s);
}

// Every stored document, one at a time (a large store need not fit in memory).
void backfill(SqlDatabase& db, int version) {
  std::vector<std::int64_t> ids;
  db.query("SELECT id FROM documents ORDER BY id", {},
           [&ids](const SqlRow& row) { ids.push_back(row.integer(0).value_or(0)); });
  const std::string get =
      "SELECT document_json FROM documents WHERE id = " + db.parameter(1, SqlType::int64);
  for (const std::int64_t id : ids) {
    std::string text;
    db.query(get, SqlParams().integer(id), [&text](const SqlRow& row) { text = row.text(0); });
    const StoredSeries series = stored_series(text, id);
    if (series.known) {
      fill_added(db, version, id, series.rows);
    } else {
      mark_unreadable(db, id);
    }
  }
}

// One migration with its bookkeeping, in one transaction; skipped if another process applied
// it first (the version is read again under the schema lock).
void apply(SqlDatabase& db, const Migration& migration) {
  SqlTransaction transaction(db);
  db.lock_schema();
  // Created (if missing) before the version is read: it also makes PostgreSQL see the tables
  // another process committed while this one waited for the lock (a table name looked up before
  // is cached until a table is locked).
  db.exec_script(kMigrationsTableSql);
  const int current = db.schema_version();
  if (current >= migration.version) return;
  const std::string tables = schema_sql(db, migration.version);
  if (!blank(tables)) db.exec_script(tables);
  if (!blank(migration.sql)) db.exec_script(migration.sql);
  if (migration.backfills) backfill(db, migration.version);
  const auto p = [&db](int n, SqlType type) { return db.parameter(n, type); };
  db.query("INSERT INTO schema_migrations (version, description, applied_at) VALUES (" +
               p(1, SqlType::int32) + ", " + p(2, SqlType::text) + ", " + p(3, SqlType::text) + ")",
           SqlParams().integer(migration.version).text(migration.description).text(utc_timestamp()),
           {});
  db.set_schema_version(migration.version);
  transaction.commit();
}

}  // namespace

// A database with no raygate schema yet that has a table of a raygate table's name is another
// program's: creating the store there failed in SQL's words ("relation documents already
// exists", exit 3; a sweep). Said as the user's to fix, before anything is written.
void refuse_foreign_tables(SqlDatabase& db) {
  std::vector<std::string> names{"schema_migrations"};
  for (const TableShape& table : store_tables()) names.push_back(table.name);
  for (const std::string& name : names) {
    // The version read after the table: a raygate creating the store commits both at once.
    if (!db.has_table(name) || db.schema_version() != 0) continue;
    throw UsageError(fmt::format(
        "results store {} is not a raygate store: it has a table '{}' that raygate did not "
        "make (another program's database?); give raygate a database of its own",
        db.location(), name));
  }
}

void check_store_tables(SqlDatabase& db) {
  const int found = db.schema_version();
  if (found == 0) return refuse_foreign_tables(db);
  // A schema version with a table it brought missing is not a raygate store either (a database
  // whose user_version its own program set: "no such table: scene_results", exit 3; a sweep).
  for (const TableShape& table : store_tables()) {
    if (created_by(table) > found || db.has_table(table.name)) continue;
    throw UsageError(fmt::format(
        "results store {} is not a raygate store: its schema version is {}, but it has no table "
        "'{}'; give raygate a database of its own",
        db.location(), found, table.name));
  }
}

int schema_version(SqlDatabase& db) { return db.schema_version(); }

int migrate(SqlDatabase& db, std::span<const Migration> migrations) {
  const int known = migrations.empty() ? 0 : migrations.back().version;
  const int found = db.schema_version();
  if (found > known) {
    throw UsageError(
        fmt::format("results store {}: schema version {} is newer than this raygate "
                    "knows ({}); use a newer raygate",
                    db.location(), found, known));
  }
  check_store_tables(db);
  for (const Migration& migration : migrations) {
    if (migration.version > found) apply(db, migration);
  }
  return db.schema_version();
}

}  // namespace raygate

// Writing documents into the store and reading them and their history rows back, once for both
// dialects. Text is compared and ordered bytewise in both (the dialect's bytewise()), so both
// backends answer every query alike.
#include "store/sql_store.h"

#include <fmt/core.h>

#include "core/error.h"
#include "core/sha256.h"
#include "core/time_text.h"
#include "core/utf8.h"
#include "store/migrate.h"
#include "store/postgres_handle.h"
#include "store/row_values.h"
#include "store/schema.h"
#include "store/store_rows.h"

namespace raygate {

namespace {

// Calls f(alias, column name, HistoryRow field) for each column history shows, in one fixed
// order: the select list and the reader of measurements() both walk it.
template <class F>
void for_each_shown(F f) {
  for (const Column& c : store_columns()) {
    if (const auto* shown = std::get_if<FieldOf<HistoryRow>>(&c.shown)) {
      f(store_table(c.table()).alias.c_str(), c.name, *shown);
    }
  }
}

std::string measurements_from() {
  std::string sql = "SELECT d.id";
  for_each_shown([&sql](const char* alias, const char* name, const FieldOf<HistoryRow>&) {
    sql += fmt::format(", {}.{}", alias, name);
  });
  return sql +
         "\nFROM scene_results s"
         "\nJOIN revisions r ON r.document_id = s.document_id AND r.role = s.role"
         "\nJOIN documents d ON d.id = s.document_id\n";
}

// One row of measurements(), checked as a document's numbers are on import: a store edited by
// hand must not change what history and alert say without a word.
HistoryRow history_row(const SqlRow& row, const std::string& location) {
  HistoryRow out;
  out.document_id = row.integer(0).value_or(0);
  int column = 1;
  for_each_shown([&](const char*, const char* name, const FieldOf<HistoryRow>& field) {
    try {
      read_field(row, column++, field, out);
    } catch (const StoredTypeError& e) {
      throw InfraError(fmt::format("results store {}: document {}: {} {}; the store is damaged",
                                   location, out.document_id, name, e.what()));
    }
  });
  check_history_row(out, location);
  return out;
}

// The filters of measurements(), parameters 1 to 7, then the scenes asked for from 8 on.
std::string measurements_where(const SqlDatabase& db, std::size_t scenes) {
  const auto p = [&db](int n) { return db.parameter(n, SqlType::text); };
  std::string sql = fmt::format(
      "WHERE ({0} = '' OR d.branch = {0}) AND ({1} = 'any' OR s.role = {1})"
      " AND ({2} OR NOT r.dirty)"
      " AND ({3} = '' OR {4} > 0) AND ({5} = '' OR r.adapter_name = {5})"
      " AND ({6} = '' OR d.suite = {6})"
      " AND ({7} = '' OR substr(s.series_id, 1, length({7})) = {7})",
      p(1), p(2), db.parameter(3, SqlType::flag), p(4), db.position("r.repository_key", p(4)), p(5),
      p(6), p(7));
  if (scenes == 0) return sql;
  sql += " AND s.scene_id IN (";
  for (std::size_t i = 0; i < scenes; ++i) {
    if (i > 0) sql += ", ";
    sql += p(static_cast<int>(i) + 8);
  }
  return sql + ")";
}

std::string measurements_order(const SqlDatabase& db) {
  return fmt::format(
      " ORDER BY r.commit_unix DESC NULLS LAST, d.started_at{0} DESC, d.id DESC, s.scene_id{0}",
      db.bytewise());
}

std::string documents_sql(const SqlDatabase& db, bool limited) {
  const std::string p1 = db.parameter(1, SqlType::text);
  const std::string p2 = db.parameter(2, SqlType::text);
  return fmt::format(
      "SELECT d.id, d.stored_at, d.branch, d.content_sha256, d.document_json FROM documents d"
      " WHERE ({0} = '' OR d.branch = {0})"
      " AND ({1} = '' OR EXISTS (SELECT 1 FROM revisions r WHERE r.document_id = d.id"
      " AND substr(r.sha, 1, length({1})) = {1}))"
      " ORDER BY d.id DESC{2}",
      p1, p2, limited ? " LIMIT " + db.parameter(3, SqlType::int64) : "");
}

// The stored text is what its content_sha256 was taken of: export gives back the imported file
// byte for byte, and a row edited by hand (one document's text copied into another, `{}`) was
// exported as if it were the document (a sweep). Said as damage, as other edited values are.
const std::string& checked_document_text(const std::string& text, const StoredDocument& stored,
                                         const std::string& location) {
  if (sha256_hex(text) == stored.content_sha256) return text;
  throw InfraError(fmt::format(
      "results store {}: document {}'s text does not match its content_sha256: edited after "
      "it was stored; the store is damaged",
      location, stored.id));
}

template <class Row>
void insert_child(SqlDatabase& db, StoreTable table, std::int64_t id, const Row& row) {
  db.query(insert_sql<Row>(db, store_table(table)), insert_params(row, id), {});
}

}  // namespace

SqlStore::SqlStore(std::unique_ptr<SqlDatabase> db) : db_(std::move(db)) { migrate(*db_); }

AddOutcome SqlStore::add(const ResultsDocument& document, const std::string& branch) {
  const DocumentRows rows = document_rows(document, branch, utc_timestamp());
  // Checked first so that re-importing stored documents takes no write lock and uses up no ids.
  if (const auto existing = find_document(rows.document.content_sha256)) return {*existing, true};
  {
    SqlTransaction transaction(*db_);
    // Another writer may have stored the same content a moment earlier: its row stands, this
    // insert returns no id and writes nothing (the UNIQUE key on content_sha256 decides).
    std::optional<std::int64_t> id;
    db_->query(insert_sql<DocumentRow>(*db_, store_table(StoreTable::documents)) +
                   " ON CONFLICT (content_sha256) DO NOTHING RETURNING id",
               insert_params(rows.document, std::nullopt),
               [&id](const SqlRow& row) { id = row.integer(0); });
    if (id) {
      for (const RevisionRow& r : rows.revisions) {
        insert_child(*db_, StoreTable::revisions, *id, r);
      }
      for (const SceneRow& s : rows.scenes) insert_child(*db_, StoreTable::scene_results, *id, s);
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

std::optional<std::int64_t> SqlStore::find_document(const std::string& content_sha256) {
  std::optional<std::int64_t> id;
  db_->query("SELECT id FROM documents WHERE content_sha256 = " + db_->parameter(1, SqlType::text),
             SqlParams().text(content_sha256), [&id](const SqlRow& row) { id = row.integer(0); });
  return id;
}

std::vector<StoredDocument> SqlStore::documents(const DocumentQuery& query) {
  SqlParams params;
  params.text(query.branch).text(query.sha_prefix);
  if (query.last > 0) params.integer(static_cast<std::int64_t>(query.last));
  std::vector<StoredDocument> out;
  db_->query(documents_sql(*db_, query.last > 0), params, [&](const SqlRow& row) {
    StoredDocument d;
    d.id = row.integer(0).value_or(0);
    d.stored_at = row.text(1);
    d.branch = repaired_utf8(row.text(2));
    d.content_sha256 = row.text(3);
    d.document =
        parse_stored_document(checked_document_text(row.text(4), d, location()), d.id, location());
    out.push_back(std::move(d));
  });
  return out;
}

std::vector<HistoryRow> SqlStore::measurements(const HistoryQuery& query) {
  SqlParams params;
  params.text(query.branch).text(query.role).flag(query.include_dirty);
  params.text(query.repository).text(query.adapter).text(query.suite).text(query.series);
  for (const std::string& scene : query.scenes) params.text(scene);
  std::vector<HistoryRow> rows;
  db_->query(measurements_from() + measurements_where(*db_, query.scenes.size()) +
                 measurements_order(*db_),
             params, [&](const SqlRow& row) { rows.push_back(history_row(row, location())); });
  return rows;
}

std::unique_ptr<ResultsStore> open_sqlite_store(const std::filesystem::path& path, StoreOpen mode,
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
  const bool existed = std::filesystem::exists(path, error);
  try {
    auto db = std::make_unique<SqliteDb>(
        SqliteDb::open(path, mode == StoreOpen::create_if_missing, busy_timeout));
    if (mode == StoreOpen::must_exist && db->schema_version() == 0) {
      // A command that only reads does not turn a file into a store (an empty file, or another
      // program's database, was given raygate's tables; a sweep).
      throw UsageError(fmt::format(
          "results store {} is not a raygate store ({}); `raygate run --store` records into a "
          "store, `raygate import FILE... --store` fills one",
          path.string(),
          std::filesystem::file_size(path, error) == 0
              ? "an empty file"
              : "an SQLite file whose schema version, PRAGMA user_version, is 0"));
    }
    // Before the journal mode is set: another program's database is refused untouched (WAL was
    // written into its header first; a sweep).
    check_store_tables(*db);
    db->configure_for_store();
    return std::make_unique<SqlStore>(std::move(db));
  } catch (...) {
    // A store this call created and could not set up (a full disk) holds nothing: it is not
    // left behind as an empty file that the next command would take for a broken store.
    if (!existed) {
      for (const char* suffix : {"", "-wal", "-shm", "-journal"}) {
        std::filesystem::remove(path.string() + suffix, error);
      }
    }
    throw;
  }
}

std::unique_ptr<ResultsStore> open_postgres_store(const std::string& url, StoreOpen mode) {
  auto db = std::make_unique<PgConnection>(PgConnection::connect(url));
  if (mode == StoreOpen::must_exist && db->schema_version() == 0) {
    refuse_foreign_tables(*db);
    throw UsageError(
        fmt::format("results store {} has no raygate tables yet; `raygate run --store URL` "
                    "records into it, `raygate import FILE... --store URL` fills it",
                    db->location()));
  }
  return std::make_unique<SqlStore>(std::move(db));
}

}  // namespace raygate

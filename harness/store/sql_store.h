// The results store written once for both backends (docs/store.md): the schema of store/schema.h,
// migrated on open (store/migrate.h), one transaction per document, the same queries, over a
// dialect handle (store/sql_database.h): an SQLite file (store/sqlite_handle.h) or a PostgreSQL
// database (store/postgres_handle.h). Adding is idempotent across processes: the content hash is
// UNIQUE and the insert says ON CONFLICT DO NOTHING, so two writers adding one document at once
// store it once.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>

#include "store/sql_database.h"
#include "store/sqlite_handle.h"
#include "store/store.h"

namespace raygate {

class SqlStore final : public ResultsStore {
 public:
  // Migrates `db` to the newest schema.
  explicit SqlStore(std::unique_ptr<SqlDatabase> db);

  AddOutcome add(const ResultsDocument& document, const std::string& branch) override;
  std::vector<StoredDocument> documents(const DocumentQuery& query) override;
  std::vector<HistoryRow> measurements(const HistoryQuery& query) override;
  std::string location() const override { return db_->location(); }

 private:
  std::optional<std::int64_t> find_document(const std::string& content_sha256);

  std::unique_ptr<SqlDatabase> db_;
};

// The SQLite file at `path` (WAL mode; several processes may write it at once, each waiting for
// the others up to `busy_timeout`). A missing file is a UsageError when it must exist.
std::unique_ptr<ResultsStore> open_sqlite_store(
    const std::filesystem::path& path, StoreOpen mode,
    std::chrono::milliseconds busy_timeout = kStoreBusyTimeout);

// The PostgreSQL database at `url` (store/postgres_url.h). One with no raygate tables is a
// UsageError when it must exist.
std::unique_ptr<ResultsStore> open_postgres_store(const std::string& url, StoreOpen mode);

}  // namespace raygate

// The team store: one PostgreSQL database that many machines and CI jobs write to at once
// (--store postgresql://USER[:PASSWORD]@HOST[:PORT]/DATABASE). The same tables and the same
// rows as the SQLite store (store/store_rows.h), schema migrated on open, one transaction per
// document. Adding is idempotent across processes: the content hash is UNIQUE and the insert
// says ON CONFLICT DO NOTHING, so two writers adding one document at once store it once
// (docs/store.md, "The team store").
#pragma once

#include "store/postgres_handle.h"
#include "store/store.h"
#include "store/store_rows.h"

namespace raygate {

class PostgresStore final : public ResultsStore {
 public:
  PostgresStore(const std::string& url, StoreOpen mode);

  AddOutcome add(const ResultsDocument& document, const std::string& branch) override;
  std::vector<StoredDocument> documents(const DocumentQuery& query) override;
  std::vector<HistoryRow> measurements(const HistoryQuery& query) override;
  std::string location() const override { return db_.location(); }

 private:
  std::optional<std::int64_t> find_document(const std::string& content_sha256);
  std::optional<std::int64_t> insert_document(const DocumentRow& row);
  void insert_revision(std::int64_t document_id, const RevisionRow& row);
  void insert_scene(std::int64_t document_id, const SceneRow& row);

  PgConnection db_;
};

}  // namespace raygate

// The embedded results store: one SQLite file (default .raygate/results.db) in WAL mode, schema
// migrated on open, one BEGIN IMMEDIATE transaction per document. Several processes may write
// to one file at once; each waits for the others up to the busy timeout (docs/store.md).
#pragma once

#include <filesystem>

#include "store/sqlite_handle.h"
#include "store/store.h"
#include "store/store_rows.h"

namespace raygate {

class SqliteStore final : public ResultsStore {
 public:
  SqliteStore(const std::filesystem::path& path, StoreOpen mode,
              std::chrono::milliseconds busy_timeout = kStoreBusyTimeout);

  AddOutcome add(const ResultsDocument& document, const std::string& branch) override;
  std::vector<StoredDocument> documents(const DocumentQuery& query) override;
  std::vector<HistoryRow> measurements(const HistoryQuery& query) override;
  std::string location() const override { return db_.path().string(); }

 private:
  std::optional<std::int64_t> find_document(const std::string& content_sha256);
  std::int64_t insert_document(const DocumentRow& row);
  void insert_revision(std::int64_t document_id, const RevisionRow& row);
  void insert_scene(std::int64_t document_id, const SceneRow& row);

  SqliteDb db_;
};

}  // namespace raygate

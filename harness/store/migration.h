// A schema migration, the shape both store backends list theirs in (store/sqlite_schema.h,
// store/postgres_schema.h), and the bookkeeping table both record them in.
#pragma once

#include <string>

namespace raygate {

struct Migration {
  int version = 0;  // 1, 2, 3, ... in order
  std::string description;
  std::string sql;
  // After `sql`, in the same transaction: fill the series columns of rows stored before them
  // from each stored document (store_rows.h stored_series).
  bool backfills_series = false;
};

// Migration 2 of both backends: the parts of each row's series (results/series.h) as columns, so
// history filters and groups by them. Valid SQL in both dialects; the rows already stored are
// filled in from their documents (backfills_series).
inline constexpr const char* kSeriesColumnsSql = R"sql(
ALTER TABLE documents ADD COLUMN timing TEXT NOT NULL DEFAULT '';
ALTER TABLE documents ADD COLUMN baseline_accel TEXT NOT NULL DEFAULT '';
ALTER TABLE revisions ADD COLUMN repository_key TEXT NOT NULL DEFAULT '';
ALTER TABLE scene_results ADD COLUMN scene_settings TEXT NOT NULL DEFAULT '';
ALTER TABLE scene_results ADD COLUMN series_id TEXT NOT NULL DEFAULT '';
CREATE INDEX revisions_repository ON revisions(repository_key, adapter_name);
CREATE INDEX scene_results_series ON scene_results(series_id);
)sql";

inline constexpr const char* kSeriesColumnsDescription =
    "series columns: documents.timing, baseline_accel; revisions.repository_key; "
    "scene_results.scene_settings, series_id";

// Valid SQL in both dialects: one row per migration applied.
inline constexpr const char* kMigrationsTableSql =
    "CREATE TABLE IF NOT EXISTS schema_migrations (version INTEGER PRIMARY KEY, "
    "description TEXT NOT NULL, applied_at TEXT NOT NULL)";

}  // namespace raygate

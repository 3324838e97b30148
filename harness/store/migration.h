// A schema migration, the shape both store backends list theirs in (store/sqlite_schema.h,
// store/postgres_schema.h), and the bookkeeping table both record them in.
#pragma once

#include <string>

namespace raygate {

struct Migration {
  int version = 0;  // 1, 2, 3, ... in order
  std::string description;
  std::string sql;
};

// Valid SQL in both dialects: one row per migration applied.
inline constexpr const char* kMigrationsTableSql =
    "CREATE TABLE IF NOT EXISTS schema_migrations (version INTEGER PRIMARY KEY, "
    "description TEXT NOT NULL, applied_at TEXT NOT NULL)";

}  // namespace raygate

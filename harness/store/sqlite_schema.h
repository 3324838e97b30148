// The SQLite store's schema as an ordered list of migrations (docs/store.md). The file's
// PRAGMA user_version is the number of the last migration applied; each migration runs in its
// own write transaction together with its row in schema_migrations, so a file is always at one
// exact version. To change the schema, append a migration; never edit a released one.
#pragma once

#include <span>
#include <string>

#include "store/migration.h"
#include "store/sqlite_handle.h"

namespace raygate {

// Every migration this raygate knows, oldest first.
std::span<const Migration> sqlite_migrations();

// PRAGMA user_version.
int schema_version(SqliteDb& db);

// Applies the migrations newer than the file's version; two processes migrating one file at once
// apply each migration once. Returns the resulting version. A file newer than `migrations`
// is a UsageError (this raygate is too old to write it).
int migrate(SqliteDb& db, std::span<const Migration> migrations);

// Write-ahead log (readers never block the writer), full sync (a committed document survives a
// power cut), foreign keys on.
void configure_connection(SqliteDb& db);

}  // namespace raygate

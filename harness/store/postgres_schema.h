// The PostgreSQL store's schema: the tables, columns, keys and indexes of the SQLite store
// (docs/store.md) in PostgreSQL's types, as an ordered list of migrations. schema_migrations
// holds one row per migration applied; its largest version is the database's version. Each
// migration runs in its own transaction holding a transaction-level advisory lock, and reads
// the version again under it, so processes opening a fresh database at once apply each
// migration exactly once. To change the schema, append a migration; never edit a released one.
#pragma once

#include <span>

#include "store/postgres_handle.h"
#include "store/migration.h"

namespace raygate {

// The advisory lock key every raygate takes while migrating ("raygate" in ASCII).
inline constexpr std::int64_t kMigrationLockKey = 0x72617967617465;

// Every migration this raygate knows, oldest first.
std::span<const Migration> postgres_migrations();

// The largest version in schema_migrations; 0 when the database has no raygate tables yet.
int schema_version(PgConnection& db);

// Applies the migrations newer than the database's version and returns the resulting version.
// A database newer than `migrations` is a UsageError (this raygate is too old to write it).
int migrate(PgConnection& db, std::span<const Migration> migrations);

}  // namespace raygate

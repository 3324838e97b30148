// Bringing a store's schema to the newest version, the same way in both dialects
// (docs/store.md, "Migrations"). Each migration runs in its own transaction together with its
// row in schema_migrations: it creates the tables whose oldest column is its own, adds the columns
// of the column tables (store/schema.h) that carry its number, runs its own SQL (indexes) and,
// if it says so, fills the columns it added on the rows stored before, from their documents.
// The version is read again under the dialect's schema lock, so processes opening one store at
// once apply each migration once; a failing migration rolls back whole.
#pragma once

#include <span>

#include "store/schema.h"
#include "store/sql_database.h"

namespace raygate {

// The number of the last migration applied; 0 for a store with no raygate tables yet.
int schema_version(SqlDatabase& db);

// A UsageError when a database with no raygate schema has a table of a raygate table's name:
// another program's database, not a store to create or read.
void refuse_foreign_tables(SqlDatabase& db);

// The same, and a UsageError when the schema version names tables the database does not have.
void check_store_tables(SqlDatabase& db);

// Applies the migrations newer than the store's version and returns the resulting version.
// A store newer than `migrations` is a UsageError (this raygate is too old to write it).
int migrate(SqlDatabase& db, std::span<const Migration> migrations = store_migrations());

}  // namespace raygate

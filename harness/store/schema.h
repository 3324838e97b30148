// The store's schema, declared once for both dialects (docs/store.md): one column table per
// stored table, each column one line saying its name, the migration that added it, the field of
// the row record (store/store_rows.h) it is written from and the field of HistoryRow it is read
// into (if history shows it), plus the ordered list of migrations. The SQL type follows from the
// field's C++ type (SqlType): std::string is text, bool a flag, int int32, std::int64_t int64
// (NOT NULL), std::optional<std::int64_t> int64 and std::optional<double> real (NULL when absent).
// To store a new column: a field in the row record, one line here with the next migration's
// number, and that migration in store_migrations().
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "store/sql_database.h"
#include "store/store.h"
#include "store/store_rows.h"

namespace raygate {

// A field of a record, by the C++ types a stored column may have.
template <class Record>
using FieldOf = std::variant<std::string Record::*, bool Record::*, int Record::*,
                             std::int64_t Record::*, std::optional<std::int64_t> Record::*,
                             std::optional<double> Record::*>;

template <class Row>
struct Column {
  int since = 1;  // the migration that adds it
  const char* name = "";
  FieldOf<Row> field;                                   // add() writes it from here
  std::variant<std::monostate, FieldOf<HistoryRow>> shown;  // measurements() reads it into here

  template <class T>
  constexpr Column(int since_migration, const char* column_name, T Row::*row_field)
      : since(since_migration), name(column_name), field(row_field) {}
  // The history field has the row field's type, so a value reads back as it was written.
  template <class T>
  constexpr Column(int since_migration, const char* column_name, T Row::*row_field,
                   T HistoryRow::*history_field)
      : since(since_migration), name(column_name), field(row_field), shown(history_field) {}
};

// The neutral type and nullability of a field's C++ type.
template <class Record>
SqlType sql_type(const FieldOf<Record>& field) {
  constexpr SqlType kTypes[] = {SqlType::text,  SqlType::flag,  SqlType::int32,
                                SqlType::int64, SqlType::int64, SqlType::real};
  return kTypes[field.index()];
}
template <class Record>
bool nullable(const FieldOf<Record>& field) {
  return std::holds_alternative<std::optional<std::int64_t> Record::*>(field) ||
         std::holds_alternative<std::optional<double> Record::*>(field);
}

// A stored column without its record type, for the DDL.
struct ColumnShape {
  std::string name;
  SqlType type = SqlType::text;
  bool nullable = false;
  int since = 1;
};

// One table: documents owns the generated id; the others are rows of one document
// (document_id), keyed within it by `key`.
struct TableShape {
  std::string name;
  std::string alias;  // in the queries: d, r, s
  bool child = false;  // has document_id; documents has the identity id instead
  std::vector<std::string> key;            // with document_id, the primary key of a child
  std::vector<std::string> constraints;    // after the columns, in SQL both dialects read
  std::vector<ColumnShape> columns;        // in the order the table lists them
};

std::span<const Column<DocumentRow>> document_columns();
std::span<const Column<RevisionRow>> revision_columns();
std::span<const Column<SceneRow>> scene_columns();

// documents, revisions, scene_results: the tables every migration works on, parents first.
std::vector<TableShape> store_tables();

// A schema migration. The columns a migration adds are those of the column tables with its
// number (added before `sql` runs); `sql` holds the rest (indexes), in SQL both dialects read.
struct Migration {
  int version = 0;  // 1, 2, 3, ... in order
  std::string description;
  std::string sql;
  // After `sql`, in the same transaction: fill the columns this migration adds on the rows stored
  // before it, from each stored document (store/migrate.h).
  bool backfills = false;
};

// Every migration this raygate knows, oldest first. Never edit a released one: append.
std::span<const Migration> store_migrations();

}  // namespace raygate

// The store's schema, declared once for both dialects (docs/store.md): one column table, each
// stored column one line saying its name, the migration that added it, the field of the row
// record (store/store_rows.h) it is written from (whose type says the table) and the field of
// HistoryRow it is read into (if history shows it), plus the ordered list of migrations. The
// SQL type follows from the field's C++ type (SqlType): std::string is text, bool a flag, int
// int32, std::int64_t int64 (NOT NULL), std::optional<std::int64_t> int64 and
// std::optional<double> real (NULL when absent).
// To store a new column: a field in the row record (and the line of store_rows.cpp that fills
// it), one line in the column table with the next migration's number, and that migration.
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
using FieldOf =
    std::variant<std::string Record::*, bool Record::*, int Record::*, std::int64_t Record::*,
                 std::optional<std::int64_t> Record::*, std::optional<double> Record::*>;

// The tables, parents first, in the order of their records in Column::field.
enum class StoreTable { documents, revisions, scene_results };

struct Column {
  int since = 1;  // the migration that adds it
  const char* name = "";
  // add() writes it from here; the record type says the table.
  std::variant<FieldOf<DocumentRow>, FieldOf<RevisionRow>, FieldOf<SceneRow>> field;
  std::variant<std::monostate, FieldOf<HistoryRow>> shown;  // measurements() reads it into here

  template <class Row, class T>
  constexpr Column(int since_migration, const char* column_name, T Row::*row_field)
      : since(since_migration),
        name(column_name),
        field(std::in_place_type<FieldOf<Row>>, row_field) {}
  // The history field has the row field's type, so a value reads back as it was written.
  template <class Row, class T>
  constexpr Column(int since_migration, const char* column_name, T Row::*row_field,
                   T HistoryRow::*history_field)
      : since(since_migration),
        name(column_name),
        field(std::in_place_type<FieldOf<Row>>, row_field),
        shown(history_field) {}

  StoreTable table() const { return static_cast<StoreTable>(field.index()); }
  // The field, when this is a column of Row's table; else nullptr.
  template <class Row>
  const FieldOf<Row>* field_of() const {
    return std::get_if<FieldOf<Row>>(&field);
  }
  SqlType type() const;
  bool nullable() const;  // the optional fields: NULL when absent
};

// The column table: every stored column, each table's in the order the table lists them.
std::span<const Column> store_columns();

// What a table is besides its columns. documents owns the generated id; the others are rows of
// one document (document_id), keyed within it by `key`.
struct TableShape {
  StoreTable table = StoreTable::documents;
  std::string name;
  std::string alias;                     // in the queries: d, r, s
  bool child = false;                    // has document_id; documents has the identity id instead
  std::vector<std::string> key;          // with document_id, the primary key of a child
  std::vector<std::string> constraints;  // after the columns, in SQL both dialects read
};

// documents, revisions, scene_results (StoreTable's order).
std::span<const TableShape> store_tables();
const TableShape& store_table(StoreTable table);

// A schema migration. The columns a migration adds are those of the column table with its
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

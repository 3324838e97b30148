// Moving the fields of the column tables (store/schema.h) between records and SQL: a row
// record's field as a statement parameter, a result column into a HistoryRow field, and the
// statements that write a whole row or the columns one migration added. Written once for every
// table and both dialects; what a column is comes from its line in the column table.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <span>
#include <string>
#include <type_traits>
#include <variant>

#include "core/utf8.h"
#include "store/schema.h"
#include "store/sql_database.h"

namespace raygate {

// Appends `record`'s `field` to `params`.
template <class Record>
void add_param(SqlParams& params, const FieldOf<Record>& field, const Record& record) {
  std::visit(
      [&](auto member) {
        const auto& value = record.*member;
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, std::string>) {
          params.text(value);
        } else if constexpr (std::is_same_v<T, bool>) {
          params.flag(value);
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
          params.real(value);
        } else {  // int, std::int64_t, std::optional<std::int64_t>
          params.integer(value);
        }
      },
      field);
}

// Reads `column` of `row` into `record`'s `field`. Text is repaired to UTF-8 (core/utf8.h): a
// store written before text was repaired where it enters, or by hand, may hold invalid bytes,
// and JSON output of them would throw.
template <class Record>
void read_field(const SqlRow& row, int column, const FieldOf<Record>& field, Record& record) {
  std::visit(
      [&](auto member) {
        auto& value = record.*member;
        using T = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<T, std::string>) {
          value = repaired_utf8(row.text(column));
        } else if constexpr (std::is_same_v<T, bool>) {
          value = row.flag(column);
        } else if constexpr (std::is_same_v<T, std::optional<double>>) {
          value = row.real(column);
        } else if constexpr (std::is_same_v<T, std::optional<std::int64_t>>) {
          value = row.integer(column);
        } else {
          value = static_cast<T>(row.integer(column).value_or(0));
        }
      },
      field);
}

// Row's column named `name`; every key of a table is one.
template <class Row>
const Column& column_named(const std::string& name) {
  for (const Column& c : store_columns()) {
    if (c.field_of<Row>() && name == c.name) return c;
  }
  throw std::logic_error("store schema: no column " + name);
}

// "INSERT INTO table (document_id, columns...) VALUES (...)": every column of Row's table.
template <class Row>
std::string insert_sql(const SqlDatabase& db, const TableShape& table) {
  std::string names = table.child ? "document_id" : "";
  std::string values = table.child ? db.parameter(1, SqlType::int64) : "";
  int number = table.child ? 1 : 0;
  for (const Column& c : store_columns()) {
    if (!c.field_of<Row>()) continue;
    if (number > 0) {
      names += ", ";
      values += ", ";
    }
    names += c.name;
    values += db.parameter(++number, c.type());
  }
  return "INSERT INTO " + table.name + " (" + names + ") VALUES (" + values + ")";
}

// The values of insert_sql<Row>'s parameters.
template <class Row>
SqlParams insert_params(const Row& row, std::optional<std::int64_t> document_id) {
  SqlParams params;
  if (document_id) params.integer(*document_id);
  for (const Column& c : store_columns()) {
    if (const FieldOf<Row>* field = c.field_of<Row>()) add_param(params, *field, row);
  }
  return params;
}

// Sets the columns migration `version` added on the stored row of `row` in document `id`.
template <class Row>
void update_added(SqlDatabase& db, const TableShape& table, int version, std::int64_t id,
                  const Row& row) {
  SqlParams params;
  params.integer(id);
  std::string sets;
  int number = 1;
  for (const Column& c : store_columns()) {
    const FieldOf<Row>* field = c.field_of<Row>();
    if (!field || c.since != version) continue;
    if (!sets.empty()) sets += ", ";
    sets += c.name;
    sets += " = " + db.parameter(++number, c.type());
    add_param(params, *field, row);
  }
  if (sets.empty()) return;
  std::string where = (table.child ? "document_id = " : "id = ") + db.parameter(1, SqlType::int64);
  for (const std::string& key : table.key) {
    const Column& c = column_named<Row>(key);
    where += " AND " + key + " = " + db.parameter(++number, c.type());
    add_param(params, *c.field_of<Row>(), row);
  }
  db.query("UPDATE " + table.name + " SET " + sets + " WHERE " + where, params, {});
}

}  // namespace raygate

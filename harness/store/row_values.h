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

// The column of `columns` named `name`; every key of a table is one.
template <class Row>
const Column<Row>& column_named(std::span<const Column<Row>> columns, const std::string& name) {
  for (const Column<Row>& c : columns) {
    if (name == c.name) return c;
  }
  throw std::logic_error("store schema: no column " + name);
}

// "INSERT INTO table (document_id, columns...) VALUES (...)": every column of the table.
template <class Row>
std::string insert_sql(const SqlDatabase& db, const TableShape& table,
                       std::span<const Column<Row>> columns) {
  std::string names = table.child ? "document_id" : "";
  std::string values = table.child ? db.parameter(1, SqlType::int64) : "";
  int number = table.child ? 1 : 0;
  for (const Column<Row>& c : columns) {
    if (number > 0) {
      names += ", ";
      values += ", ";
    }
    names += c.name;
    values += db.parameter(++number, sql_type<Row>(c.field));
  }
  return "INSERT INTO " + table.name + " (" + names + ") VALUES (" + values + ")";
}

template <class Row>
SqlParams insert_params(std::span<const Column<Row>> columns, const Row& row,
                        std::optional<std::int64_t> document_id) {
  SqlParams params;
  if (document_id) params.integer(*document_id);
  for (const Column<Row>& c : columns) add_param(params, c.field, row);
  return params;
}

// Sets the columns migration `version` added on the stored row of `row` in document `id`.
template <class Row>
void update_added(SqlDatabase& db, const TableShape& table, std::span<const Column<Row>> columns,
                  int version, std::int64_t id, const Row& row) {
  SqlParams params;
  params.integer(id);
  std::string sets;
  int number = 1;
  for (const Column<Row>& c : columns) {
    if (c.since != version) continue;
    if (!sets.empty()) sets += ", ";
    sets += c.name;
    sets += " = " + db.parameter(++number, sql_type<Row>(c.field));
    add_param(params, c.field, row);
  }
  if (sets.empty()) return;
  std::string where = (table.child ? "document_id = " : "id = ") + db.parameter(1, SqlType::int64);
  for (const std::string& key : table.key) {
    const Column<Row>& c = column_named(columns, key);
    where += " AND " + key + " = " + db.parameter(++number, sql_type<Row>(c.field));
    add_param(params, c.field, row);
  }
  db.query("UPDATE " + table.name + " SET " + sets + " WHERE " + where, params, {});
}

}  // namespace raygate

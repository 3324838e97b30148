// The thin dialect layer under the one SQL store (store/sql_store.h): what differs between SQLite
// and PostgreSQL, and nothing else. The schema (store/store_columns.h), the migrations
// (store/sql_schema.h) and every query are written once against this interface; the SQLite
// handle (store/sqlite_handle.h) and the PostgreSQL handle (store/postgres_handle.h) implement it.
// What both dialects already share is not here: CREATE TABLE, ALTER TABLE ... ADD COLUMN,
// `INSERT ... ON CONFLICT (...) DO NOTHING RETURNING`, NULLS LAST, substr and length.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace raygate {

// A stored column's type, in no dialect's words.
enum class SqlType {
  int32,  // a small count (documents.schema_version): INTEGER in both
  int64,  // ids, seconds, rounds: INTEGER in SQLite (64-bit), BIGINT in PostgreSQL
  real,   // REAL in SQLite (8 bytes), DOUBLE PRECISION in PostgreSQL
  text,   // TEXT
  flag,   // a boolean: 0/1 INTEGER in SQLite, BOOLEAN in PostgreSQL
};

// The values of a statement's parameters 1, 2, ... in order; nullopt is SQL NULL.
class SqlParams {
 public:
  using Value = std::variant<std::monostate, std::int64_t, double, std::string, bool>;

  // Distinct names, so a string literal never binds as a flag.
  SqlParams& text(const std::string& value);
  SqlParams& integer(std::optional<std::int64_t> value);
  SqlParams& flag(bool value);
  SqlParams& real(std::optional<double> value);

  const std::vector<Value>& values() const { return values_; }

 private:
  std::vector<Value> values_;
};

// A number column holding text, as only a hand edit of an SQLite file makes (SQLite keeps what it
// is given; 'abc' read as a number is 0). what() says what it holds; the reader adds where.
class StoredTypeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One row of a query's result. Columns are numbered from 0; NULL reads as "", nullopt or false.
class SqlRow {
 public:
  virtual ~SqlRow() = default;
  virtual std::string text(int column) const = 0;
  virtual std::optional<std::int64_t> integer(int column) const = 0;
  virtual std::optional<double> real(int column) const = 0;
  virtual bool flag(int column) const = 0;
};

// A connection to one store database, in its dialect.
class SqlDatabase {
 public:
  virtual ~SqlDatabase() = default;

  // Where the store lives, for messages (a path; a URL without its password).
  virtual std::string location() const = 0;

  // Runs one statement with `params`, calling `each_row` for every row it returns.
  virtual void query(const std::string& sql, const SqlParams& params,
                     const std::function<void(const SqlRow&)>& each_row) = 0;
  // Constant SQL of several statements and no parameters (the schema's DDL).
  virtual void exec_script(const std::string& sql) = 0;

  // Parameter `number` (from 1) of `type`, as it stands in SQL: "?3", "$3::text". PostgreSQL
  // is told the type, since `$1 = ''` alone does not say it.
  virtual std::string parameter(int number, SqlType type) const = 0;
  virtual std::string type_name(SqlType type) const = 0;
  // The generated 64-bit primary key of documents, after the column's name.
  virtual std::string identity_key() const = 0;
  // 1-based position of `needle` in `haystack` (0: absent), as an SQL expression.
  virtual std::string position(const std::string& haystack, const std::string& needle) const = 0;
  // What follows an ORDER BY text expression so that text sorts bytewise in any locale.
  virtual std::string bytewise() const = 0;

  // A write transaction (SQLite takes the write lock up front; PostgreSQL is READ COMMITTED).
  virtual void begin() = 0;
  virtual void commit() = 0;
  virtual void rollback() noexcept = 0;  // never throws: a dead connection rolls back by itself

  // In a migration's transaction, before the version is read: makes other processes migrating
  // the same store wait until this transaction ends.
  virtual void lock_schema() = 0;
  // The number of the last migration applied; 0 for a store with no raygate tables. A UsageError
  // when the table it is read from is another program's.
  virtual int schema_version() = 0;
  // Whether the database has a table of that name, whoever made it.
  virtual bool has_table(const std::string& name) = 0;
  // Records `version` where schema_version() reads it (schema_migrations holds a row per
  // migration in both dialects; SQLite also keeps the number in the file's header).
  virtual void set_schema_version(int version) = 0;

 protected:
  SqlDatabase() = default;
  SqlDatabase(SqlDatabase&&) noexcept = default;
};

// begin() now; rollback() from the destructor unless commit() ran.
class SqlTransaction {
 public:
  explicit SqlTransaction(SqlDatabase& db) : db_(db) { db_.begin(); }
  SqlTransaction(const SqlTransaction&) = delete;
  SqlTransaction& operator=(const SqlTransaction&) = delete;
  ~SqlTransaction() {
    if (open_) db_.rollback();
  }
  void commit() {
    open_ = false;  // a failed COMMIT has ended the transaction too
    db_.commit();
  }

 private:
  SqlDatabase& db_;
  bool open_ = true;
};

}  // namespace raygate

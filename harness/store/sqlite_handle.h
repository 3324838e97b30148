// RAII over the SQLite C API: a connection, which is the SQLite side of the store's dialect
// layer (store/sql_database.h), and a prepared statement. Every failure becomes a raygate error
// carrying SQLite's message, the database path and the SQL it was running; "database is locked"
// (another writer held the file past the busy timeout) is an InfraError, a file that is not a
// database a UsageError.
#pragma once

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "store/sql_database.h"

struct sqlite3;
struct sqlite3_stmt;

namespace raygate {

inline constexpr std::chrono::milliseconds kStoreBusyTimeout{30000};

class SqliteDb final : public SqlDatabase {
 public:
  // Opens (and with `create`, creates) the file; sets the busy timeout and extended codes.
  static SqliteDb open(const std::filesystem::path& path, bool create,
                       std::chrono::milliseconds busy_timeout = kStoreBusyTimeout);
  SqliteDb(SqliteDb&& other) noexcept;
  SqliteDb& operator=(SqliteDb&&) = delete;
  SqliteDb(const SqliteDb&) = delete;
  ~SqliteDb() override;

  // Write-ahead log (readers never block the writer), full sync (a committed document survives
  // a power cut), foreign keys on: how the store uses its file.
  void configure_for_store();

  // Runs statements that return no rows (several, separated by ';').
  void exec(const std::string& sql);
  // Throws the raygate error for SQLite result `code` while running `sql`.
  [[noreturn]] void fail(int code, const std::string& sql) const;

  // The dialect layer. The schema's version is the file's PRAGMA user_version; BEGIN IMMEDIATE
  // takes the write lock up front, so two writers never deadlock upgrading a read, and it is the
  // schema lock too.
  std::string location() const override { return path_.string(); }
  void query(const std::string& sql, const SqlParams& params,
             const std::function<void(const SqlRow&)>& each_row) override;
  void exec_script(const std::string& sql) override { exec(sql); }
  std::string parameter(int number, SqlType type) const override;
  std::string type_name(SqlType type) const override;
  std::string identity_key() const override { return "INTEGER PRIMARY KEY"; }
  std::string position(const std::string& haystack, const std::string& needle) const override;
  std::string bytewise() const override { return ""; }  // BINARY is SQLite's default
  void begin() override { exec("BEGIN IMMEDIATE"); }
  void commit() override;
  void rollback() noexcept override;
  void lock_schema() override {}
  int schema_version() override;
  bool has_table(const std::string& name) override;
  void set_schema_version(int version) override;

  sqlite3* get() const { return db_; }
  const std::filesystem::path& path() const { return path_; }
  std::chrono::milliseconds busy_timeout() const { return busy_timeout_; }

 private:
  SqliteDb(sqlite3* db, std::filesystem::path path, std::chrono::milliseconds busy_timeout)
      : db_(db), path_(std::move(path)), busy_timeout_(busy_timeout) {}

  sqlite3* db_ = nullptr;
  std::filesystem::path path_;
  std::chrono::milliseconds busy_timeout_;
};

class SqliteStatement {
 public:
  SqliteStatement(SqliteDb& db, std::string sql);
  SqliteStatement(const SqliteStatement&) = delete;
  SqliteStatement& operator=(const SqliteStatement&) = delete;
  ~SqliteStatement();

  // Parameters are numbered from 1, as in SQLite.
  // Distinct names, so a string literal never binds as a flag. nullopt binds NULL.
  SqliteStatement& bind_text(int index, const std::string& value);
  SqliteStatement& bind_int(int index, std::optional<std::int64_t> value);
  SqliteStatement& bind_flag(int index, bool value);
  SqliteStatement& bind_real(int index, std::optional<double> value);

  bool step();  // true: a row is ready; false: done
  void run();   // steps to the end, ignoring rows

  // Columns are numbered from 0, as in SQLite. NULL reads as "", 0 or nullopt.
  std::string text(int column) const;
  std::int64_t integer(int column) const;
  std::optional<std::int64_t> optional_integer(int column) const;
  std::optional<double> real(int column) const;

 private:
  void check_bind(int code);

  SqliteDb& db_;
  std::string sql_;
  sqlite3_stmt* statement_ = nullptr;
};

}  // namespace raygate

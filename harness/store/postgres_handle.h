// RAII over libpq: a connection (PGconn), which is the PostgreSQL side of the store's dialect
// layer (store/sql_database.h), a query's result (PGresult) and parameters. Values always travel
// as parameters of PQexecParams in text form, never inside the SQL. Every failure becomes a
// raygate error naming the server without its password, the server's message with its SQLSTATE
// and the SQL that was running: a server that cannot be reached or a connection lost midway is
// an InfraError saying to check the server and retry.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "store/postgres_url.h"
#include "store/sql_database.h"

struct pg_conn;    // PGconn
struct pg_result;  // PGresult

namespace raygate {

// The advisory lock key every raygate takes while migrating ("raygate" in ASCII).
inline constexpr std::int64_t kMigrationLockKey = 0x72617967617465;

// How long connecting may take when the URL sets no connect_timeout.
inline constexpr std::chrono::seconds kPostgresConnectTimeout{10};

// Parameters $1, $2, ... in order, as text; nullopt is SQL NULL.
class PgParams {
 public:
  // Distinct names, so a string literal never binds as a flag.
  PgParams& text(const std::string& value);
  PgParams& integer(std::optional<std::int64_t> value);
  PgParams& flag(bool value);
  PgParams& real(std::optional<double> value);  // shortest text that reads back the same double

  int size() const { return static_cast<int>(values_.size()); }
  std::vector<const char*> pointers() const;  // for PQexecParams; valid while this lives

 private:
  std::vector<std::optional<std::string>> values_;
};

class PgResult {
 public:
  explicit PgResult(pg_result* result);
  PgResult(PgResult&&) noexcept = default;
  PgResult& operator=(PgResult&&) noexcept = default;

  int rows() const;
  // Rows and columns are numbered from 0. NULL reads as "", 0, false or nullopt.
  bool is_null(int row, int column) const;
  std::string text(int row, int column) const;
  std::int64_t integer(int row, int column) const;
  std::optional<std::int64_t> optional_integer(int row, int column) const;
  bool flag(int row, int column) const;
  std::optional<double> real(int row, int column) const;

 private:
  struct Clear {
    void operator()(pg_result* result) const;
  };
  std::unique_ptr<pg_result, Clear> result_;
};

class PgConnection final : public SqlDatabase {
 public:
  // Connects (UsageError for a malformed URL, InfraError for a server that cannot be reached
  // or refuses the login); sets UTF-8 and exact float text, and silences server notices.
  static PgConnection connect(const std::string& url);

  // One statement; its values as parameters. Returns the rows (none for commands).
  PgResult exec(const std::string& sql, const PgParams& params = {});
  // Constant SQL with several statements and no values (the schema's DDL).
  void exec_script(const std::string& sql) override;

  // The dialect layer. Transactions are READ COMMITTED whatever the server's default: adding a
  // document relies on each statement seeing what other writers committed before it
  // (docs/store.md, "The team store"). The schema lock is a transaction-level advisory lock
  // (kMigrationLockKey): CREATE TABLE IF NOT EXISTS alone races on the catalog. The version is
  // the largest in schema_migrations.
  std::string location() const override { return url_.redacted; }  // without the password
  void query(const std::string& sql, const SqlParams& params,
             const std::function<void(const SqlRow&)>& each_row) override;
  std::string parameter(int number, SqlType type) const override;
  std::string type_name(SqlType type) const override;
  std::string identity_key() const override { return "BIGSERIAL PRIMARY KEY"; }
  std::string position(const std::string& haystack, const std::string& needle) const override;
  std::string bytewise() const override { return " COLLATE \"C\""; }
  void begin() override { exec("BEGIN ISOLATION LEVEL READ COMMITTED"); }
  void commit() override { exec("COMMIT"); }  // a failed COMMIT ends the transaction too
  void rollback() noexcept override;
  void lock_schema() override;
  int schema_version() override;
  bool has_table(const std::string& name) override;
  void set_schema_version(int) override {}  // the row in schema_migrations says it
  pg_conn* get() const { return conn_.get(); }

 private:
  struct Finish {
    void operator()(pg_conn* conn) const;
  };
  PgConnection(pg_conn* conn, PostgresUrl url) : conn_(conn), url_(std::move(url)) {}
  [[noreturn]] void fail(const pg_result* result, const std::string& sql) const;
  PgResult checked(pg_result* result, const std::string& sql) const;

  std::unique_ptr<pg_conn, Finish> conn_;
  PostgresUrl url_;
};

}  // namespace raygate

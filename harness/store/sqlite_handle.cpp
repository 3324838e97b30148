// SQLite connections and statements, with errors that say where and what, and SQLite's dialect.
#include "store/sqlite_handle.h"

#include <fmt/core.h>
#include <sqlite3.h>

#include <thread>

#include "core/error.h"
#include "core/utf8.h"

namespace raygate {

namespace {

// The SQL as one short line, for messages.
std::string sql_context(const std::string& sql) {
  std::string line;
  bool space = false;
  for (const char c : sql) {
    if (c == '\n' || c == '\t' || c == ' ') {
      space = !line.empty();
      continue;
    }
    if (space) line += ' ';
    space = false;
    line += c;
  }
  return line.size() > 72 ? line.substr(0, 69) + "..." : line;
}

// SQLite cannot open a store whose -wal or -shm file is a symbolic link (it refuses to follow
// one), and says only "unable to open database file": the link is named.
std::string side_file_note(const std::filesystem::path& path) {
  for (const char* suffix : {"-wal", "-shm"}) {
    std::error_code error;
    const std::filesystem::path side = path.string() + suffix;
    if (std::filesystem::is_symlink(std::filesystem::symlink_status(side, error))) {
      return fmt::format("; {} is a symbolic link, which SQLite does not open: remove it",
                         side.string());
    }
  }
  return "";
}

[[noreturn]] void throw_sqlite_error(int code, const std::string& message,
                                     const std::filesystem::path& path, const std::string& sql,
                                     std::chrono::milliseconds busy_timeout) {
  const int primary = code & 0xff;
  const std::string where =
      sql.empty() ? std::string("opening it") : "running: " + sql_context(sql);
  if (primary == SQLITE_BUSY || primary == SQLITE_LOCKED) {
    throw InfraError(fmt::format(
        "results store {}: database is locked ({}; waited {} ms while {}): another raygate is "
        "writing to it; retry when it has finished",
        path.string(), message, busy_timeout.count(), where));
  }
  if (primary == SQLITE_NOTADB) {
    throw UsageError(
        fmt::format("results store {}: not an SQLite database ({}); --store must "
                    "name a raygate results database",
                    path.string(), message));
  }
  throw InfraError(fmt::format("results store {}: SQLite error {} ({}) while {}{}", path.string(),
                               code, message, where, side_file_note(path)));
}

}  // namespace

SqliteDb SqliteDb::open(const std::filesystem::path& path, bool create,
                        std::chrono::milliseconds busy_timeout) {
  // SQLite opens a device (/dev/null) and fails later, in a disk I/O error of its own words.
  std::error_code error;
  if (std::filesystem::exists(path, error) && !std::filesystem::is_regular_file(path, error)) {
    throw UsageError(fmt::format(
        "results store {}: not a regular file (a folder, device, FIFO or socket); --store must "
        "name a raygate results database",
        path.string()));
  }
  sqlite3* db = nullptr;
  const int flags = SQLITE_OPEN_READWRITE | (create ? SQLITE_OPEN_CREATE : 0);
  const int code = sqlite3_open_v2(path.c_str(), &db, flags, nullptr);
  if (code != SQLITE_OK) {
    const std::string message = db ? sqlite3_errmsg(db) : sqlite3_errstr(code);
    sqlite3_close(db);
    throw_sqlite_error(code, message, path, "", busy_timeout);
  }
  sqlite3_extended_result_codes(db, 1);
  sqlite3_busy_timeout(db, static_cast<int>(busy_timeout.count()));
  return SqliteDb(db, path, busy_timeout);
}

SqliteDb::SqliteDb(SqliteDb&& other) noexcept
    : SqlDatabase(std::move(other)),
      db_(other.db_),
      path_(std::move(other.path_)),
      busy_timeout_(other.busy_timeout_) {
  other.db_ = nullptr;
}

SqliteDb::~SqliteDb() { sqlite3_close_v2(db_); }

void SqliteDb::exec(const std::string& sql) {
  const int code = sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr);
  if (code != SQLITE_OK) fail(code, sql);
}

void SqliteDb::fail(int code, const std::string& sql) const {
  throw_sqlite_error(code, sqlite3_errmsg(db_), path_, sql, busy_timeout_);
}

SqliteStatement::SqliteStatement(SqliteDb& db, std::string sql) : db_(db), sql_(std::move(sql)) {
  const int code = sqlite3_prepare_v2(db_.get(), sql_.c_str(), -1, &statement_, nullptr);
  if (code != SQLITE_OK) db_.fail(code, sql_);
}

SqliteStatement::~SqliteStatement() { sqlite3_finalize(statement_); }

void SqliteStatement::check_bind(int code) {
  if (code != SQLITE_OK) db_.fail(code, sql_);
}

SqliteStatement& SqliteStatement::bind_text(int index, const std::string& value) {
  check_bind(sqlite3_bind_text(statement_, index, value.data(), static_cast<int>(value.size()),
                               SQLITE_TRANSIENT));
  return *this;
}

SqliteStatement& SqliteStatement::bind_int(int index, std::optional<std::int64_t> value) {
  check_bind(value ? sqlite3_bind_int64(statement_, index, *value)
                   : sqlite3_bind_null(statement_, index));
  return *this;
}

SqliteStatement& SqliteStatement::bind_flag(int index, bool value) {
  return bind_int(index, value ? 1 : 0);
}

SqliteStatement& SqliteStatement::bind_real(int index, std::optional<double> value) {
  check_bind(value ? sqlite3_bind_double(statement_, index, *value)
                   : sqlite3_bind_null(statement_, index));
  return *this;
}

bool SqliteStatement::step() {
  const int code = sqlite3_step(statement_);
  if (code == SQLITE_ROW) return true;
  if (code == SQLITE_DONE) return false;
  db_.fail(code, sql_);
}

void SqliteStatement::run() {
  while (step()) {
  }
}

std::string SqliteStatement::text(int column) const {
  const unsigned char* value = sqlite3_column_text(statement_, column);
  if (value == nullptr) return {};
  return std::string(reinterpret_cast<const char*>(value),
                     static_cast<std::size_t>(sqlite3_column_bytes(statement_, column)));
}

std::int64_t SqliteStatement::integer(int column) const {
  return sqlite3_column_int64(statement_, column);
}

namespace {

// Text or bytes where a number was asked for: refused, not read as 0 (a sweep's hand edit hid a
// regression from alert).
void refuse_text_as_number(sqlite3_stmt* statement, int column) {
  const int type = sqlite3_column_type(statement, column);
  if (type != SQLITE_TEXT && type != SQLITE_BLOB) return;
  const unsigned char* text = sqlite3_column_text(statement, column);
  const std::string held = text == nullptr ? "" : reinterpret_cast<const char*>(text);
  throw StoredTypeError(fmt::format("holds {} '{}', not a number",
                                    type == SQLITE_TEXT ? "text" : "bytes",
                                    repaired_utf8(held.substr(0, 40))));
}

}  // namespace

std::optional<std::int64_t> SqliteStatement::optional_integer(int column) const {
  if (sqlite3_column_type(statement_, column) == SQLITE_NULL) return std::nullopt;
  refuse_text_as_number(statement_, column);
  return sqlite3_column_int64(statement_, column);
}

std::optional<double> SqliteStatement::real(int column) const {
  if (sqlite3_column_type(statement_, column) == SQLITE_NULL) return std::nullopt;
  refuse_text_as_number(statement_, column);
  return sqlite3_column_double(statement_, column);
}

namespace {

// The current row of a statement, for the dialect layer's readers.
class StatementRow final : public SqlRow {
 public:
  explicit StatementRow(const SqliteStatement& statement) : statement_(statement) {}
  std::string text(int column) const override { return statement_.text(column); }
  std::optional<std::int64_t> integer(int column) const override {
    return statement_.optional_integer(column);
  }
  std::optional<double> real(int column) const override { return statement_.real(column); }
  bool flag(int column) const override { return statement_.integer(column) != 0; }

 private:
  const SqliteStatement& statement_;
};

void bind(SqliteStatement& statement, int index, const SqlParams::Value& value) {
  if (const auto* text = std::get_if<std::string>(&value)) {
    statement.bind_text(index, *text);
  } else if (const auto* integer = std::get_if<std::int64_t>(&value)) {
    statement.bind_int(index, *integer);
  } else if (const auto* real = std::get_if<double>(&value)) {
    statement.bind_real(index, *real);
  } else if (const auto* flag = std::get_if<bool>(&value)) {
    statement.bind_flag(index, *flag);
  } else {
    statement.bind_int(index, std::nullopt);
  }
}

}  // namespace

void SqliteDb::query(const std::string& sql, const SqlParams& params,
                     const std::function<void(const SqlRow&)>& each_row) {
  SqliteStatement statement(*this, sql);
  const std::vector<SqlParams::Value>& values = params.values();
  for (std::size_t i = 0; i < values.size(); ++i) {
    bind(statement, static_cast<int>(i) + 1, values[i]);
  }
  while (statement.step()) {
    if (each_row) each_row(StatementRow(statement));
  }
}

std::string SqliteDb::parameter(int number, SqlType) const { return fmt::format("?{}", number); }

std::string SqliteDb::type_name(SqlType type) const {
  // By SqlType: int32, int64 (SQLite's integers are 64-bit), real, text, flag (0/1).
  constexpr const char* kNames[] = {"INTEGER", "INTEGER", "REAL", "TEXT", "INTEGER"};
  return kNames[static_cast<int>(type)];
}

std::string SqliteDb::position(const std::string& haystack, const std::string& needle) const {
  return fmt::format("instr({}, {})", haystack, needle);
}

void SqliteDb::commit() {
  try {
    exec("COMMIT");
  } catch (...) {
    rollback();  // a COMMIT that failed (busy) leaves the transaction open
    throw;
  }
}

void SqliteDb::rollback() noexcept {
  // A failed ROLLBACK leaves SQLite to roll back when the connection closes; never throw here.
  sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
}

int SqliteDb::schema_version() {
  int version = 0;
  query("PRAGMA user_version", {},
        [&version](const SqlRow& row) { version = static_cast<int>(*row.integer(0)); });
  return version;
}

bool SqliteDb::has_table(const std::string& name) {
  bool found = false;
  query("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?1", SqlParams().text(name),
        [&found](const SqlRow&) { found = true; });
  return found;
}

void SqliteDb::set_schema_version(int version) {
  exec(fmt::format("PRAGMA user_version = {}", version));
}

// Switching to WAL takes an exclusive lock that the busy handler does not always wait for
// (a fresh file opened by several processes at once): retry until the busy timeout.
void SqliteDb::configure_for_store() {
  const auto deadline = std::chrono::steady_clock::now() + busy_timeout_;
  for (;;) {
    const int code = sqlite3_exec(db_, "PRAGMA journal_mode = WAL", nullptr, nullptr, nullptr);
    if (code == SQLITE_OK) break;
    const bool busy = (code & 0xff) == SQLITE_BUSY || (code & 0xff) == SQLITE_LOCKED;
    if (!busy || std::chrono::steady_clock::now() > deadline) {
      fail(code, "PRAGMA journal_mode = WAL");
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  exec("PRAGMA synchronous = FULL");
  exec("PRAGMA foreign_keys = ON");
}

}  // namespace raygate

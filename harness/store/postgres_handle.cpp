// libpq connections and results, with errors that say where and what to do, and PostgreSQL's
// dialect.
#include "store/postgres_handle.h"

#include <fmt/core.h>
#include <libpq-fe.h>

#include <charconv>
#include <type_traits>

#include "core/error.h"

namespace raygate {

namespace {

// `text` as one line of at most `max_chars` (SQL and server messages span several).
std::string one_line(const std::string& text, std::size_t max_chars) {
  std::string line;
  bool space = false;
  for (const char c : text) {
    if (c == '\n' || c == '\t' || c == ' ' || c == '\r') {
      space = !line.empty();
      continue;
    }
    if (space) line += ' ';
    space = false;
    line += c;
  }
  return line.size() > max_chars ? line.substr(0, max_chars - 3) + "..." : line;
}

std::string field(const pg_result* result, int code) {
  const char* value = result ? PQresultErrorField(result, code) : nullptr;
  return value ? value : "";
}

// The server's primary message and its detail; libpq's own message when there is no result
// (a connection that broke before the server could answer).
std::string error_message(const pg_result* result, pg_conn* conn) {
  std::string message = field(result, PG_DIAG_MESSAGE_PRIMARY);
  const std::string detail = field(result, PG_DIAG_MESSAGE_DETAIL);
  if (!detail.empty()) message += "; " + detail;
  if (message.empty()) message = PQerrorMessage(conn);
  return one_line(message, 400);
}

// Connection exceptions (08...) and operator intervention (57P01 shutdown, 57P02 crash, ...).
bool connection_lost(const std::string& sqlstate, pg_conn* conn) {
  return PQstatus(conn) == CONNECTION_BAD || sqlstate.starts_with("08") ||
         sqlstate.starts_with("57P");
}

// Server notices ("relation already exists, skipping") are not for raygate's users.
void ignore_notice(void*, const char*) {}

template <typename Number>
Number parse_number(const char* text, int length) {
  Number value{};
  std::from_chars(text, text + length, value);
  return value;
}

}  // namespace

PgParams& PgParams::text(const std::string& value) {
  values_.emplace_back(value);
  return *this;
}

PgParams& PgParams::integer(std::optional<std::int64_t> value) {
  values_.push_back(value ? std::optional<std::string>(std::to_string(*value)) : std::nullopt);
  return *this;
}

PgParams& PgParams::flag(bool value) {
  values_.emplace_back(value ? "true" : "false");
  return *this;
}

PgParams& PgParams::real(std::optional<double> value) {
  values_.push_back(value ? std::optional<std::string>(fmt::format("{}", *value)) : std::nullopt);
  return *this;
}

std::vector<const char*> PgParams::pointers() const {
  std::vector<const char*> out;
  for (const std::optional<std::string>& value : values_) {
    out.push_back(value ? value->c_str() : nullptr);
  }
  return out;
}

void PgResult::Clear::operator()(pg_result* result) const { PQclear(result); }

PgResult::PgResult(pg_result* result) : result_(result) {}

int PgResult::rows() const { return PQntuples(result_.get()); }

bool PgResult::is_null(int row, int column) const {
  return PQgetisnull(result_.get(), row, column) != 0;
}

std::string PgResult::text(int row, int column) const {
  return std::string(PQgetvalue(result_.get(), row, column),
                     static_cast<std::size_t>(PQgetlength(result_.get(), row, column)));
}

std::int64_t PgResult::integer(int row, int column) const {
  return optional_integer(row, column).value_or(0);
}

std::optional<std::int64_t> PgResult::optional_integer(int row, int column) const {
  if (is_null(row, column)) return std::nullopt;
  return parse_number<std::int64_t>(PQgetvalue(result_.get(), row, column),
                                    PQgetlength(result_.get(), row, column));
}

bool PgResult::flag(int row, int column) const {
  return !is_null(row, column) && PQgetvalue(result_.get(), row, column)[0] == 't';
}

std::optional<double> PgResult::real(int row, int column) const {
  if (is_null(row, column)) return std::nullopt;
  return parse_number<double>(PQgetvalue(result_.get(), row, column),
                              PQgetlength(result_.get(), row, column));
}

void PgConnection::Finish::operator()(pg_conn* conn) const { PQfinish(conn); }

PgConnection PgConnection::connect(const std::string& url) {
  PostgresUrl parsed = parse_postgresql_url(url);
  // The URL's own settings win over those before "dbname"; those after it win over the URL.
  const std::string timeout = std::to_string(kPostgresConnectTimeout.count());
  const char* const keywords[] = {"connect_timeout", "fallback_application_name", "dbname",
                                  "client_encoding", nullptr};
  const char* const values[] = {timeout.c_str(), "raygate", url.c_str(), "UTF8", nullptr};
  PgConnection db(PQconnectdbParams(keywords, values, 1), std::move(parsed));
  if (!db.conn_) throw InfraError("results store " + db.location() + ": libpq is out of memory");
  if (PQstatus(db.get()) != CONNECTION_OK) {
    throw InfraError(fmt::format(
        "results store {}: cannot connect ({}); check that the PostgreSQL server is running "
        "and reachable there and that the URL's user, password and database are right",
        db.location(), scrub_secrets(one_line(PQerrorMessage(db.get()), 400), db.url_)));
  }
  PQsetNoticeProcessor(db.get(), ignore_notice, nullptr);
  // Servers before PostgreSQL 12 print doubles with 15 digits unless asked for more; 3 gives
  // every server's round-trip exact text.
  db.exec("SET extra_float_digits = 3");
  return db;
}

PgResult PgConnection::checked(pg_result* result, const std::string& sql) const {
  PgResult owned(result);  // cleared however this ends
  const ExecStatusType status = result ? PQresultStatus(result) : PGRES_FATAL_ERROR;
  if (status != PGRES_COMMAND_OK && status != PGRES_TUPLES_OK) fail(result, sql);
  return owned;
}

PgResult PgConnection::exec(const std::string& sql, const PgParams& params) {
  const std::vector<const char*> values = params.pointers();
  return checked(PQexecParams(conn_.get(), sql.c_str(), params.size(), nullptr, values.data(),
                              nullptr, nullptr, 0),
                 sql);
}

void PgConnection::exec_script(const std::string& sql) {
  checked(PQexec(conn_.get(), sql.c_str()), sql);
}

void PgConnection::fail(const pg_result* result, const std::string& sql) const {
  const std::string sqlstate = field(result, PG_DIAG_SQLSTATE);
  const std::string message = scrub_secrets(error_message(result, conn_.get()), url_);
  const std::string where = "running: " + one_line(sql, 72);
  if (connection_lost(sqlstate, conn_.get())) {
    throw InfraError(fmt::format(
        "results store {}: lost the connection to the server ({}) while {}; what was not "
        "committed was not stored; check that the server is up and retry",
        location(), message, where));
  }
  if (sqlstate == "40001" || sqlstate == "40P01") {
    throw InfraError(fmt::format(
        "results store {}: conflict with another writer (SQLSTATE {}: {}) while {}; retry",
        location(), sqlstate, message, where));
  }
  if (sqlstate == "42501") {
    throw UsageError(fmt::format(
        "results store {}: permission denied ({}) while {}; the URL's user needs the rights "
        "of docs/store.md on the database",
        location(), message, where));
  }
  throw InfraError(fmt::format("results store {}: PostgreSQL error{} ({}) while {}", location(),
                               sqlstate.empty() ? "" : " " + sqlstate, message, where));
}

namespace {

// One row of a result, for the dialect layer's readers.
class ResultRow final : public SqlRow {
 public:
  ResultRow(const PgResult& result, int row) : result_(result), row_(row) {}
  std::string text(int column) const override { return result_.text(row_, column); }
  std::optional<std::int64_t> integer(int column) const override {
    return result_.optional_integer(row_, column);
  }
  std::optional<double> real(int column) const override { return result_.real(row_, column); }
  bool flag(int column) const override { return result_.flag(row_, column); }

 private:
  const PgResult& result_;
  int row_;
};

// Every value travels as text: PostgreSQL reads it as the type its parameter is cast to.
std::optional<std::string> text_of(const SqlParams::Value& value) {
  return std::visit(
      [](const auto& v) -> std::optional<std::string> {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>) return std::nullopt;
        if constexpr (std::is_same_v<T, std::string>) return v;
        if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
        // Integers exactly; doubles as the shortest text that reads back the same double.
        if constexpr (std::is_same_v<T, std::int64_t> || std::is_same_v<T, double>) {
          return fmt::format("{}", v);
        }
      },
      value);
}

PgParams pg_params(const SqlParams& params) {
  PgParams out;
  for (const SqlParams::Value& value : params.values()) {
    const std::optional<std::string> text = text_of(value);
    if (text) {
      out.text(*text);
    } else {
      out.integer(std::nullopt);
    }
  }
  return out;
}

}  // namespace

void PgConnection::query(const std::string& sql, const SqlParams& params,
                         const std::function<void(const SqlRow&)>& each_row) {
  const PgResult result = exec(sql, pg_params(params));
  if (!each_row) return;
  for (int i = 0; i < result.rows(); ++i) each_row(ResultRow(result, i));
}

std::string PgConnection::parameter(int number, SqlType type) const {
  return fmt::format("${}::{}", number, type_name(type));
}

std::string PgConnection::type_name(SqlType type) const {
  // By SqlType: int32, int64, real, text, flag.
  constexpr const char* kNames[] = {"INTEGER", "BIGINT", "DOUBLE PRECISION", "TEXT", "BOOLEAN"};
  return kNames[static_cast<int>(type)];
}

std::string PgConnection::position(const std::string& haystack, const std::string& needle) const {
  return fmt::format("strpos({}, {})", haystack, needle);
}

void PgConnection::rollback() noexcept {
  // A ROLLBACK that fails means the connection is gone, and the server rolls back a dead
  // connection's transaction itself.
  if (PQstatus(conn_.get()) == CONNECTION_OK) PQclear(PQexec(conn_.get(), "ROLLBACK"));
}

void PgConnection::lock_schema() {
  exec("SELECT pg_advisory_xact_lock($1)", PgParams().integer(kMigrationLockKey));
}

int PgConnection::schema_version() {
  if (!has_table("schema_migrations")) return 0;
  // Another program's table of the name (a text version: "COALESCE types text and integer cannot
  // be matched", exit 3; a sweep) is no raygate store.
  const bool ours = exec(
                        "SELECT count(*) = 3 FROM information_schema.columns WHERE table_schema = "
                        "current_schema() AND table_name = 'schema_migrations' AND "
                        "((column_name = 'version' AND data_type = 'integer') OR (column_name IN "
                        "('description', 'applied_at') AND data_type = 'text'))")
                        .flag(0, 0);
  if (!ours) {
    throw UsageError(fmt::format(
        "results store {} is not a raygate store: its table schema_migrations is another "
        "program's; give raygate a database of its own",
        location()));
  }
  return static_cast<int>(
      exec("SELECT coalesce(max(version), 0) FROM schema_migrations").integer(0, 0));
}

bool PgConnection::has_table(const std::string& name) {
  return exec("SELECT to_regclass($1::text) IS NOT NULL", PgParams().text(name)).flag(0, 0);
}

}  // namespace raygate

// A real, throwaway PostgreSQL server for the team store's tests: the Debian binaries' initdb
// into a temporary directory, postgres (a child of the test, ended with it) on a free loopback
// port with its socket in that directory, stopped and deleted at the end. One server per test
// binary, started by a GoogleTest environment before the first test (linking
// postgres_server.cpp registers it); each test takes a fresh database. PostgreSQL refuses to
// run as root, so under root (CI) the server commands run as the `postgres` system user.
// Missing binaries fail every test with a message saying what to install: these tests never
// skip silently.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/fs.h"
#include "core/process.h"

struct pg_conn;

namespace raygate::test {

class PostgresServer {
 public:
  // Throws std::runtime_error saying what is missing when the server cannot be started.
  PostgresServer();
  ~PostgresServer();
  PostgresServer(const PostgresServer&) = delete;
  PostgresServer& operator=(const PostgresServer&) = delete;

  int port() const { return port_; }
  // A new, empty database collated in English (ICU en-US, not bytes); returns its URL. The
  // URL carries a password, which the server
  // (trust authentication on loopback) ignores, so tests can check it is never printed.
  std::string create_database();
  std::string url(const std::string& database) const;

  static constexpr const char* kPassword = "s3cret-pw";

 private:
  ProcessSpec server_spec(std::vector<std::string> argv, const std::string& log_name) const;
  void start();
  std::string wait_until_ready() const;  // "" when ready, else why not
  std::filesystem::path data_dir() const { return dir_.path() / "data"; }

  TempDir dir_{"raygate-pg"};
  std::filesystem::path bin_dir_;
  int port_ = 0;
  int databases_ = 0;
  std::optional<Process> postmaster_;
};

// The server of this test binary (started before the first test).
PostgresServer& postgres_server();

// A plain libpq connection for looking inside a database or sabotaging it.
class RawConnection {
 public:
  explicit RawConnection(const std::string& url);
  ~RawConnection();
  RawConnection(const RawConnection&) = delete;
  RawConnection& operator=(const RawConnection&) = delete;

  // The first column of the first row ("" for none); throws std::runtime_error on an error.
  std::string text(const std::string& sql);
  // Runs SQL (several statements allowed); false when it failed.
  bool exec(const std::string& sql);
  int backend_pid() const;

 private:
  pg_conn* conn_ = nullptr;
};

}  // namespace raygate::test

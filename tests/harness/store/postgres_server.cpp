// The test PostgreSQL server's life: find the binaries, initdb, start, databases, stop.
#include "postgres_server.h"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <libpq-fe.h>
#include <netinet/in.h>
#include <pwd.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace raygate::test {

namespace {

namespace fs = std::filesystem;

constexpr const char* kUser = "raygate";
constexpr const char* kServerAccount = "postgres";  // made by Debian's postgresql package

bool has_server_binaries(const fs::path& dir) {
  return fs::exists(dir / "initdb") && fs::exists(dir / "postgres");
}

// Debian keeps the binaries off PATH in /usr/lib/postgresql/VERSION/bin; the newest version
// wins. Else an initdb on PATH (a symlink is followed to the real directory).
fs::path find_bin_dir() {
  std::vector<std::pair<int, fs::path>> found;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator("/usr/lib/postgresql", error)) {
    const std::string version = entry.path().filename().string();
    if (has_server_binaries(entry.path() / "bin") && !version.empty() &&
        std::all_of(version.begin(), version.end(), ::isdigit)) {
      found.emplace_back(std::stoi(version), entry.path() / "bin");
    }
  }
  if (!found.empty()) return std::max_element(found.begin(), found.end())->second;
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  for (std::size_t start = 0; start <= dirs.size();) {
    std::size_t end = dirs.find(':', start);
    if (end == std::string::npos) end = dirs.size();
    const fs::path initdb = fs::path(dirs.substr(start, end - start)) / "initdb";
    if (fs::exists(initdb, error)) {
      const fs::path real = fs::canonical(initdb, error).parent_path();
      if (!error && has_server_binaries(real)) return real;
    }
    start = end + 1;
  }
  throw std::runtime_error(
      "no PostgreSQL server binaries (initdb, postgres) in /usr/lib/postgresql/*/bin "
      "or on PATH: install the Debian package `postgresql` (ci/install-deps does); the team "
      "store's tests need a real server");
}

// A port nobody listens on now: the kernel's pick for a socket bound to port 0.
int free_loopback_port() {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t length = sizeof address;
  if (fd < 0 || ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0 ||
      ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length) != 0) {
    if (fd >= 0) ::close(fd);
    throw std::runtime_error("cannot find a free port on 127.0.0.1");
  }
  ::close(fd);
  return ntohs(address.sin_port);
}

const passwd& server_account() {
  const passwd* account = ::getpwnam(kServerAccount);
  if (account == nullptr) {
    throw std::runtime_error(
        "the tests run as root, which PostgreSQL refuses, and there is no `postgres` user to "
        "run the server as: install the Debian package `postgresql`, which creates it");
  }
  return *account;
}

// A child that has exited but is not reaped yet is a zombie ('Z' in /proc/PID/stat).
bool has_exited(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return true;
  const std::size_t paren = line.rfind(')');
  return paren == std::string::npos || paren + 2 >= line.size() || line[paren + 2] == 'Z';
}

void append(const fs::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::app);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

}  // namespace

PostgresServer::PostgresServer() : bin_dir_(find_bin_dir()) {
  if (::geteuid() == 0) {
    const passwd& account = server_account();
    if (::chown(dir_.path().c_str(), account.pw_uid, account.pw_gid) != 0) {
      throw std::runtime_error("cannot hand " + dir_.path().string() + " to user postgres");
    }
  }
  // No fsync anywhere: the data dies with the test, and speed matters (every CI push). The
  // server writes its own log file (the logging collector), so nothing fills our pipes.
  ProcessSpec initdb_spec =
      server_spec({(bin_dir_ / "initdb").string(), "-D", data_dir().string(), "-U", kUser,
                   "--auth=trust", "--encoding=UTF8", "--no-locale", "--no-sync"},
                  "initdb.log");
  initdb_spec.timeout = std::chrono::seconds(90);
  const ProcessResult initdb = run_process(initdb_spec);
  if (!initdb.succeeded()) {
    throw std::runtime_error("initdb " + initdb.describe() + ": " +
                             log_tail(dir_.path() / "initdb.log"));
  }
  append(data_dir() / "postgresql.conf",
         "\nlisten_addresses = '127.0.0.1'\nunix_socket_directories = '" + dir_.path().string() +
             "'\nfsync = off\nsynchronous_commit = off\nfull_page_writes = off\n"
             "max_connections = 60\nshared_buffers = 16MB\nlogging_collector = on\n"
             "log_directory = '" +
             dir_.path().string() + "'\nlog_filename = 'server.log'\n");
  start();
}

// The port is free when picked but could be taken before postgres binds it: a few tries.
void PostgresServer::start() {
  for (int attempt = 1;; ++attempt) {
    port_ = free_loopback_port();
    postmaster_.emplace(Process::start(server_spec(
        {(bin_dir_ / "postgres").string(), "-D", data_dir().string(), "-p", std::to_string(port_)},
        "postmaster.log")));
    const std::string problem = wait_until_ready();
    if (problem.empty()) return;
    postmaster_.reset();  // kills and reaps what is left of it
    if (attempt == 3) throw std::runtime_error(problem);
  }
}

// Accepting connections within a minute, else why not (the logs' last lines).
std::string PostgresServer::wait_until_ready() const {
  const std::string conninfo = "postgresql://" + std::string(kUser) +
                               "@127.0.0.1:" + std::to_string(port_) +
                               "/postgres?connect_timeout=2";
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline) {
    if (PQping(conninfo.c_str()) == PQPING_OK) return {};
    if (has_exited(postmaster_->pid())) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return "postgres did not start on port " + std::to_string(port_) + ": " +
         log_tail(dir_.path() / "postmaster.log") + " " + log_tail(dir_.path() / "server.log");
}

// Immediate shutdown (SIGQUIT): nothing needs saving, the directory goes next.
PostgresServer::~PostgresServer() {
  if (!postmaster_) return;
  ::kill(postmaster_->pid(), SIGQUIT);
  postmaster_->wait();
}

// Under root, the command runs as the postgres account (initdb and postgres refuse root). The
// parent-death signal (kept across exec) ends the server with this test binary, however that
// ends: a crash or a CTest timeout leaves no server behind.
ProcessSpec PostgresServer::server_spec(std::vector<std::string> argv,
                                        const std::string& log_name) const {
  std::vector<std::string> prefix = {"setpriv", "--pdeathsig=SIGQUIT"};
  if (::geteuid() == 0) {
    prefix.insert(prefix.end(), {std::string("--reuid=") + kServerAccount,
                                 std::string("--regid=") + kServerAccount, "--init-groups"});
  }
  argv.insert(argv.begin(), prefix.begin(), prefix.end());
  ProcessSpec spec;
  spec.argv = std::move(argv);
  spec.working_directory = dir_.path();  // readable by the server account, unlike root's cwd
  spec.stdout_path = dir_.path() / log_name;
  spec.stderr_path = spec.stdout_path;
  return spec;
}

std::string PostgresServer::url(const std::string& database) const {
  return "postgresql://" + std::string(kUser) + ":" + kPassword +
         "@127.0.0.1:" + std::to_string(port_) + "/" + database;
}

std::string PostgresServer::create_database() {
  const std::string name = "raygate_test_" + std::to_string(++databases_);
  RawConnection admin(url("postgres"));
  // English collation (ICU), as a team's server may well have, not bytes: it orders "Gears"
  // after "gears" and both after "balls", so a query that forgot COLLATE "C" shows.
  if (!admin.exec("CREATE DATABASE " + name +
                  " TEMPLATE template0 LOCALE_PROVIDER icu ICU_LOCALE 'en-US' LOCALE 'C'")) {
    throw std::runtime_error("cannot create database " + name);
  }
  return url(name);
}

RawConnection::RawConnection(const std::string& url) : conn_(PQconnectdb(url.c_str())) {
  if (PQstatus(conn_) != CONNECTION_OK) {
    const std::string message = PQerrorMessage(conn_);
    PQfinish(conn_);
    throw std::runtime_error("cannot connect to the test server: " + message);
  }
}

RawConnection::~RawConnection() { PQfinish(conn_); }

std::string RawConnection::text(const std::string& sql) {
  PGresult* result = PQexec(conn_, sql.c_str());
  const ExecStatusType status = PQresultStatus(result);
  std::string out;
  if (status == PGRES_TUPLES_OK && PQntuples(result) > 0) out = PQgetvalue(result, 0, 0);
  const std::string error = PQresultErrorMessage(result);
  PQclear(result);
  if (status != PGRES_TUPLES_OK && status != PGRES_COMMAND_OK) {
    throw std::runtime_error(sql + ": " + error);
  }
  return out;
}

bool RawConnection::exec(const std::string& sql) {
  PGresult* result = PQexec(conn_, sql.c_str());
  const ExecStatusType status = PQresultStatus(result);
  PQclear(result);
  return status == PGRES_TUPLES_OK || status == PGRES_COMMAND_OK;
}

int RawConnection::backend_pid() const { return PQbackendPID(conn_); }

namespace {

// Owns the binary's one server from before the first test to after the last. When it cannot
// start, the environment fails and so does every test that asks for the server, each with the
// reason (a fatal failure here would only mark the tests skipped).
class PostgresEnvironment : public ::testing::Environment {
 public:
  void SetUp() override {
    try {
      server_ = std::make_unique<PostgresServer>();
    } catch (const std::exception& e) {
      error_ = std::string("cannot start a PostgreSQL server for the tests: ") + e.what();
      ADD_FAILURE() << error_;
    }
  }
  void TearDown() override { server_.reset(); }
  PostgresServer& server() {
    if (!server_) throw std::runtime_error(error_);
    return *server_;
  }

 private:
  std::unique_ptr<PostgresServer> server_;
  std::string error_ = "the PostgreSQL test server was not started";
};

PostgresEnvironment* const environment =
    static_cast<PostgresEnvironment*>(::testing::AddGlobalTestEnvironment(new PostgresEnvironment));

}  // namespace

PostgresServer& postgres_server() { return environment->server(); }

}  // namespace raygate::test

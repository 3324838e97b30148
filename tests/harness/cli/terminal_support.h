// Running the built raygate binary on a pseudo-terminal (forkpty), for what it does only when
// its output is a terminal: colour, and a progress line rewritten in place.
#pragma once

#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace raygate::test {

struct TerminalRun {
  int exit_code = -1;
  std::string out;  // what the terminal showed: stdout and stderr, as a user sees them
};

// `env`: variables set (a value) or removed (nullopt) before raygate starts.
inline TerminalRun run_on_terminal(const std::vector<std::string>& args,
                                   const std::filesystem::path& dir,
                                   const std::map<std::string, std::optional<std::string>>& env) {
  int master = -1;
  const pid_t pid = ::forkpty(&master, nullptr, nullptr, nullptr);
  if (pid < 0) return {};
  if (pid == 0) {  // the child: only async-signal-safe-enough calls before exec
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    for (const auto& [name, value] : env) {
      if (value) {
        ::setenv(name.c_str(), value->c_str(), 1);
      } else {
        ::unsetenv(name.c_str());
      }
    }
    std::vector<char*> argv{const_cast<char*>(RAYGATE_EXE)};
    for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
    argv.push_back(nullptr);
    ::execv(RAYGATE_EXE, argv.data());
    ::_exit(127);
  }
  TerminalRun run;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(master, buffer, sizeof buffer);
    if (n > 0) {
      run.out.append(buffer, static_cast<std::size_t>(n));
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      break;  // EIO once the child's side is closed
    }
  }
  ::close(master);
  int status = 0;
  ::waitpid(pid, &status, 0);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

}  // namespace raygate::test

#include "core/interrupt.h"

#include <fcntl.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>

namespace raygate {
namespace {

// The handler's state. Globals because a signal handler can reach nothing else; all of it
// lock-free atomics, which a handler may touch.
static_assert(std::atomic<int>::is_always_lock_free && std::atomic<pid_t>::is_always_lock_free &&
              std::atomic<std::int64_t>::is_always_lock_free);
constexpr std::size_t kMaxChildGroups = 256;
// The signals that ask raygate to stop: Ctrl-C, a polite kill, a closed terminal or session,
// Ctrl-\ (whose default, a core dump, would lose the scenes measured and orphan the tracer).
constexpr int kStopSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
constinit std::atomic<int> g_signal{0};
constinit std::atomic<std::int64_t> g_signal_ns{0};  // when g_signal was recorded (monotonic)
constinit std::atomic<int> g_scopes{0};
constinit std::atomic<int> g_pipe_read{-1};
constinit std::atomic<int> g_pipe_write{-1};
constinit std::array<std::atomic<pid_t>, kMaxChildGroups> g_groups{};

void wake_pollers() {
  const int fd = g_pipe_write.load();
  if (fd < 0) return;
  const char byte = 1;
  [[maybe_unused]] const ssize_t ignored = ::write(fd, &byte, 1);  // non-blocking; full is fine
}

std::int64_t monotonic_ns() {
  timespec now{};
  ::clock_gettime(CLOCK_MONOTONIC, &now);  // async-signal-safe
  return std::int64_t{now.tv_sec} * 1'000'000'000 + now.tv_nsec;
}

// The one line raygate leaves when a signal ends it at once (the shell says only "Terminated",
// a CI log nothing): which signal. A constant per signal, as write() of a fixed buffer is all a
// handler may do.
void say_ended_at_once(int sig) {
  const char* line = "raygate: ended at once by a signal\n";
  switch (sig) {
    case SIGINT: line = "raygate: ended at once by SIGINT\n"; break;
    case SIGTERM: line = "raygate: ended at once by SIGTERM\n"; break;
    case SIGHUP: line = "raygate: ended at once by SIGHUP\n"; break;
    case SIGQUIT: line = "raygate: ended at once by SIGQUIT\n"; break;
    default: break;
  }
  [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, line, std::strlen(line));
}

// Records the first request (decide_stop: record), lets a repeat of it pass (ignore), or, when
// nobody would look or this is a second signal, kills the children's groups and dies of the
// signal, as without a handler (end_now). Two threads may run it at once for two copies of one
// signal: the one whose exchange fails decides again against the one that won.
extern "C" void on_stop_signal(int sig) {
  const int saved_errno = errno;
  const std::int64_t now = monotonic_ns();
  int recorded = g_signal.load();
  StopAction action = decide_stop(sig, now, recorded, g_signal_ns.load(), g_scopes.load() > 0);
  if (action == StopAction::record) {
    g_signal_ns.store(now);  // before the flag: a repeat that sees the flag sees a time
    if (g_signal.compare_exchange_strong(recorded, sig)) {
      wake_pollers();
      errno = saved_errno;
      return;
    }
    action = decide_stop(sig, now, recorded, g_signal_ns.load(), true);
  }
  if (action == StopAction::ignore) {
    errno = saved_errno;
    return;
  }
  for (const std::atomic<pid_t>& group : g_groups) {
    if (const pid_t g = group.load(); g > 0) ::kill(-g, SIGKILL);
  }
  say_ended_at_once(sig);
  ::signal(sig, SIG_DFL);
  ::raise(sig);  // blocked while this handler runs; delivered, and fatal, when it returns
  errno = saved_errno;
}

void install_handler(int sig) {
  struct sigaction old {};
  if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) return;  // nohup, `&`
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  for (const int stop : kStopSignals) sigaddset(&action.sa_mask, stop);
  action.sa_flags = SA_RESTART;  // code between children need not expect EINTR
  ::sigaction(sig, &action, nullptr);
}

}  // namespace

namespace {

ExitCode exit_code_of(int signal) {
  switch (signal) {
    case SIGTERM: return ExitCode::terminated;
    case SIGHUP: return ExitCode::hung_up;
    case SIGQUIT: return ExitCode::quit;
    default: return ExitCode::interrupted;
  }
}

}  // namespace

Interrupted::Interrupted(int signal, const std::string& message)
    : Error(exit_code_of(signal), message), signal_(signal) {}

void install_interrupt_handlers() {
  if (g_pipe_write.load() >= 0) return;
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC | O_NONBLOCK) != 0) {
    throw InfraError(std::string("cannot create the interrupt pipe: ") + std::strerror(errno));
  }
  g_pipe_read.store(fds[0]);
  g_pipe_write.store(fds[1]);
  for (const int stop : kStopSignals) install_handler(stop);
}

int interrupt_signal() { return g_signal.load(); }

int interrupt_fd() { return g_pipe_read.load(); }

void request_interrupt(int signal) {
  int none = 0;
  if (g_signal.load() == 0) g_signal_ns.store(monotonic_ns());
  if (g_signal.compare_exchange_strong(none, signal)) wake_pollers();
}

void throw_if_interrupted(const std::string& doing) {
  if (const int sig = interrupt_signal(); sig != 0) {
    throw Interrupted(sig, "interrupted by " + signal_name(sig) + " " + doing);
  }
}

std::string signal_name(int signal) {
  const char* abbrev = sigabbrev_np(signal);
  return abbrev != nullptr ? std::string("SIG") + abbrev : "signal " + std::to_string(signal);
}

void clear_interrupt_for_testing() {
  g_signal.store(0);
  g_signal_ns.store(0);
  if (const int fd = g_pipe_read.load(); fd >= 0) {
    char buffer[64];
    while (::read(fd, buffer, sizeof buffer) > 0) {
    }
  }
}

InterruptScope::InterruptScope() { g_scopes.fetch_add(1); }
InterruptScope::~InterruptScope() { g_scopes.fetch_sub(1); }

int register_child_group(pid_t group) {
  for (std::size_t i = 0; i < g_groups.size(); ++i) {
    pid_t empty = 0;
    if (g_groups[i].compare_exchange_strong(empty, group)) return static_cast<int>(i);
  }
  return -1;
}

void release_child_group(int slot) {
  if (slot >= 0) g_groups[static_cast<std::size_t>(slot)].store(0);
}

bool is_registered_child(pid_t pid) {
  for (const std::atomic<pid_t>& group : g_groups) {
    if (group.load() == pid) return true;
  }
  return false;
}

}  // namespace raygate

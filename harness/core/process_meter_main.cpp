// raygate-meter: starts one program and reports the resources that program (and the children it
// waited for) used, its peak resident memory above all. Why a separate process: Linux folds the
// old address space's peak RSS into a process's maxrss at execve, and a fork or posix_spawn child
// starts from its parent's (vfork: the very same) address space. A tracer started by raygate
// directly therefore reports raygate's own peak (~130 MB), whatever it uses itself. This program
// is tiny, so the peak it hands on to the program it starts is ~1 MB.
//
// Usage: raygate-meter [--cgroup PROCS_FILE] REPORT_FD PROGRAM [ARG...]
// With --cgroup it first joins that cgroup (writes its pid to PROCS_FILE, a memory cgroup's
// cgroup.procs that raygate made: core/memory_cgroup.h), so PROGRAM and all it starts are
// counted there together; raygate reads the cgroup's peak after this process ended.
// It runs PROGRAM in its own process group (raygate's), with its stdio, environment and CPU
// mask, forwards the signals one sends to a single process, and ends as PROGRAM ended (the same
// exit status, or the same signal). On REPORT_FD it writes one line:
//   "rusage <user_us> <system_us> <max_rss_kib> <wall_ns> <joined>"   after PROGRAM was reaped
//     (joined: 1 when it ran inside the --cgroup, else 0; max_rss_kib is the largest single
//     process's peak, wait4's), or
//   "spawn_failed <errno>"                                   when PROGRAM could not start.
// It uses only the C library: a C++ runtime would raise the very floor it is there to keep low.
#include <errno.h>
#include <fcntl.h>
#include <linux/magic.h>
#include <sys/vfs.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char** environ;

namespace {

volatile sig_atomic_t g_child = 0;  // a signal handler can reach nothing else

constexpr int kForwarded[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2};

void forward(int sig) {
  if (g_child > 0) kill(g_child, sig);
}

long long now_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<long long>(t.tv_sec) * 1000000000LL + t.tv_nsec;
}

long long micros(const timeval& tv) {
  return static_cast<long long>(tv.tv_sec) * 1000000LL + tv.tv_usec;
}

void report(int fd, const char* line) {
  const size_t size = strlen(line);
  size_t done = 0;
  while (done < size) {
    const ssize_t n = write(fd, line + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // raygate is gone; nothing to tell
    done += static_cast<size_t>(n);
  }
}

// The signals this process forwards are blocked until the child's pid is known, and restored
// to their defaults in the child.
int start(char** argv, pid_t& pid) {
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t defaults;
  sigset_t empty;
  sigemptyset(&defaults);
  sigemptyset(&empty);
  for (const int sig : kForwarded) sigaddset(&defaults, sig);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setsigdefault(&attr, &defaults);
  posix_spawnattr_setsigmask(&attr, &empty);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  const int status = posix_spawnp(&pid, argv[0], nullptr, &attr, argv, environ);
  posix_spawnattr_destroy(&attr);
  return status;
}

void install_forwarding(sigset_t& blocked) {
  sigemptyset(&blocked);
  for (const int sig : kForwarded) sigaddset(&blocked, sig);
  sigprocmask(SIG_BLOCK, &blocked, nullptr);
  struct sigaction action {};
  action.sa_handler = forward;
  sigemptyset(&action.sa_mask);
  for (const int sig : kForwarded) sigaction(sig, &action, nullptr);
}

// Ends this process the way the child ended, without a core file of its own.
[[noreturn]] void end_like(int status) {
  if (WIFEXITED(status)) _exit(WEXITSTATUS(status));
  const int sig = WIFSIGNALED(status) ? WTERMSIG(status) : SIGKILL;
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
  signal(sig, SIG_DFL);
  sigset_t only;
  sigemptyset(&only);
  sigaddset(&only, sig);
  sigprocmask(SIG_UNBLOCK, &only, nullptr);
  raise(sig);
  _exit(128 + sig);
}

// Moves this process into the cgroup whose cgroup.procs is `procs_file`; 1 when it did. Only a
// file of a cgroup file system (v2, or v1's memory hierarchy) is written: given any other path (a results document), the
// meter wrote its pid over the file's start (sweep 13).
int join_cgroup(const char* procs_file) {
  const int fd = open(procs_file, O_WRONLY | O_CLOEXEC);
  if (fd < 0) return 0;
  struct statfs where {};
  if (fstatfs(fd, &where) != 0 ||
      (where.f_type != CGROUP2_SUPER_MAGIC && where.f_type != CGROUP_SUPER_MAGIC)) {
    close(fd);
    return 0;
  }
  char pid[32];
  snprintf(pid, sizeof pid, "%d\n", static_cast<int>(getpid()));
  const ssize_t n = write(fd, pid, strlen(pid));
  close(fd);
  return n == static_cast<ssize_t>(strlen(pid)) ? 1 : 0;
}

}  // namespace

int main(int argc, char** argv) {
  int joined = 0;
  if (argc >= 3 && strcmp(argv[1], "--cgroup") == 0) {
    joined = join_cgroup(argv[2]);
    argc -= 2;
    argv += 2;
  }
  if (argc < 3) {
    static constexpr char kUsage[] =
        "usage: raygate-meter [--cgroup PROCS_FILE] REPORT_FD PROGRAM [ARG...]\n";
    report(2, kUsage);
    return 2;
  }
  const int report_fd = atoi(argv[1]);
  fcntl(report_fd, F_SETFD, FD_CLOEXEC);  // the program and its children must not hold it
  sigset_t blocked;
  install_forwarding(blocked);
  const long long started = now_ns();
  pid_t pid = -1;
  const int spawn_error = start(argv + 2, pid);
  char line[160];
  if (spawn_error != 0) {
    snprintf(line, sizeof line, "spawn_failed %d\n", spawn_error);
    report(report_fd, line);
    return 127;
  }
  g_child = pid;
  sigprocmask(SIG_UNBLOCK, &blocked, nullptr);
  int status = 0;
  rusage usage{};
  pid_t reaped = -1;
  do {
    reaped = wait4(pid, &status, 0, &usage);
  } while (reaped < 0 && errno == EINTR);
  const long long wall = now_ns() - started;
  g_child = 0;
  if (reaped != pid) return 126;
  snprintf(line, sizeof line, "rusage %lld %lld %ld %lld %d\n", micros(usage.ru_utime),
           micros(usage.ru_stime), usage.ru_maxrss, wall, joined);
  report(report_fd, line);
  end_like(status);
}

#include "core/process.h"

#include <fcntl.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <deque>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <utility>

#include "core/error.h"
#include "core/interrupt.h"
#include "core/paths.h"
#include "core/strays.h"

extern char** environ;

namespace raygate {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_of(const timeval& tv) {
  return static_cast<double>(tv.tv_sec) + static_cast<double>(tv.tv_usec) * 1e-6;
}

int open_log(const std::filesystem::path& path) {
  if (path.empty()) return -1;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw InfraError("cannot create log " + path.string() + ": " + std::strerror(errno));
  return fd;
}

void close_fd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

std::vector<std::string> build_environment(const ProcessSpec& spec) {
  std::map<std::string, std::string> vars;
  if (spec.inherit_environment) {
    for (char** e = environ; e != nullptr && *e != nullptr; ++e) {
      const std::string entry(*e);
      const auto eq = entry.find('=');
      if (eq != std::string::npos) vars[entry.substr(0, eq)] = entry.substr(eq + 1);
    }
  }
  for (const auto& [key, value] : spec.environment) vars[key] = value;
  std::vector<std::string> out;
  for (const auto& [key, value] : vars) out.push_back(key + "=" + value);
  return out;
}

std::vector<char*> c_strings(std::vector<std::string>& strings) {
  std::vector<char*> out;
  for (std::string& s : strings) out.push_back(s.data());
  out.push_back(nullptr);
  return out;
}

// posix_spawn has no affinity attribute; the child inherits the calling thread's mask, so the
// mask is set around the spawn and restored after it.
class ScopedAffinity {
 public:
  explicit ScopedAffinity(const std::vector<int>& cpus) {
    if (cpus.empty()) return;
    if (sched_getaffinity(0, sizeof saved_, &saved_) != 0) return;
    cpu_set_t wanted;
    CPU_ZERO(&wanted);
    for (const int cpu : cpus) CPU_SET(cpu, &wanted);
    active_ = sched_setaffinity(0, sizeof wanted, &wanted) == 0;
  }
  ~ScopedAffinity() {
    if (active_) sched_setaffinity(0, sizeof saved_, &saved_);
  }
  ScopedAffinity(const ScopedAffinity&) = delete;
  ScopedAffinity& operator=(const ScopedAffinity&) = delete;

 private:
  cpu_set_t saved_{};
  bool active_ = false;
};

// The fd on which raygate-meter writes its report (its argv[1]).
constexpr int kMeterReportFd = 3;

// What raygate-meter wrote: its "rusage ..." or "spawn_failed ..." line.
struct MeterReport {
  bool spawn_failed = false;
  int spawn_errno = 0;
  bool has_usage = false;
  long long user_us = 0;
  long long system_us = 0;
  long max_rss_kib = 0;
  long long wall_ns = 0;
  bool joined_cgroup = false;  // the program ran inside the cgroup raygate made for it
};

MeterReport parse_meter_report(const std::string& text) {
  MeterReport report;
  if (std::sscanf(text.c_str(), "spawn_failed %d", &report.spawn_errno) == 1) {
    report.spawn_failed = true;
  } else {
    int joined = 0;
    const int fields =
        std::sscanf(text.c_str(), "rusage %lld %lld %ld %lld %d", &report.user_us,
                    &report.system_us, &report.max_rss_kib, &report.wall_ns, &joined);
    report.has_usage = fields >= 4;
    report.joined_cgroup = fields == 5 && joined == 1;
  }
  return report;
}

}  // namespace

std::filesystem::path meter_executable() {
  const std::filesystem::path path = executable_directory() / "raygate-meter";
  if (::access(path.c_str(), X_OK) != 0) {
    throw InfraError("raygate-meter is missing beside raygate (" + path.string() +
                     "): it measures a tracer's own memory; build or install it with raygate");
  }
  return path;
}

std::string ProcessResult::describe() const {
  std::ostringstream out;
  switch (outcome) {
    case ProcessOutcome::exited: out << "exited with status " << exit_code; break;
    case ProcessOutcome::signaled:
      out << "killed by signal " << signal << " (" << sigabbrev_np(signal) << ")";
      break;
    case ProcessOutcome::timed_out:
      out << "timed out after " << std::fixed << std::setprecision(1) << wall_seconds << " s";
      // The seconds past the limit are the grace a process gets after SIGTERM (a sweep read 22 s
      // for a 20 s limit as a wrong clock).
      if (signal == SIGKILL) out << " (it ignored SIGTERM at the limit and was killed)";
      break;
    case ProcessOutcome::spawn_failed: out << "could not start: " << spawn_error; break;
  }
  return out.str();
}

namespace {

// The child's standard output and error, and raygate-meter's report when metered: [0] is read
// by raygate, [1] is the child's, closed here once the child holds it (else no end of file).
struct ChildPipes {
  int out[2] = {-1, -1};
  int err[2] = {-1, -1};
  int meter[2] = {-1, -1};

  void close_child_ends() {
    close_fd(out[1]);
    close_fd(err[1]);
    close_fd(meter[1]);
  }
};

ChildPipes open_child_pipes(bool metered) {
  ChildPipes pipes;
  if (::pipe2(pipes.out, O_CLOEXEC) != 0 || ::pipe2(pipes.err, O_CLOEXEC) != 0) {
    throw InfraError(std::string("cannot create pipes: ") + std::strerror(errno));
  }
  if (metered && ::pipe2(pipes.meter, O_CLOEXEC) != 0) {
    throw InfraError(std::string("cannot create a pipe: ") + std::strerror(errno));
  }
  return pipes;
}

// What the child's descriptors are: standard input from a file (or /dev/null, so a tracer
// never waits on a terminal), output and error into raygate's pipes, the meter's report fd, and
// the working directory.
class SpawnFileActions {
 public:
  SpawnFileActions(const ProcessSpec& spec, const ChildPipes& pipes)
      : stdin_path_(spec.stdin_path.empty() ? "/dev/null" : spec.stdin_path.string()) {
    posix_spawn_file_actions_init(&actions_);
    posix_spawn_file_actions_addopen(&actions_, 0, stdin_path_.c_str(), O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions_, pipes.out[1], 1);
    posix_spawn_file_actions_adddup2(&actions_, pipes.err[1], 2);
    if (spec.metered) posix_spawn_file_actions_adddup2(&actions_, pipes.meter[1], kMeterReportFd);
    if (!spec.working_directory.empty()) {
      posix_spawn_file_actions_addchdir_np(&actions_, spec.working_directory.c_str());
    }
  }
  ~SpawnFileActions() { posix_spawn_file_actions_destroy(&actions_); }
  SpawnFileActions(const SpawnFileActions&) = delete;
  SpawnFileActions& operator=(const SpawnFileActions&) = delete;
  const posix_spawn_file_actions_t* get() const { return &actions_; }

 private:
  std::string stdin_path_;
  posix_spawn_file_actions_t actions_{};
};

// How the child starts: no signal blocked, and the signals raygate catches or ignores back at
// their defaults, so it starts as it would alone (under nohup too); in a process group of its
// own, so a timeout kills the tracer's children too.
class SpawnAttributes {
 public:
  SpawnAttributes() {
    posix_spawnattr_init(&attributes_);
    sigset_t no_signals;
    sigset_t default_signals;
    sigemptyset(&no_signals);
    sigemptyset(&default_signals);
    for (const int sig : {SIGPIPE, SIGINT, SIGTERM, SIGHUP, SIGQUIT}) {
      sigaddset(&default_signals, sig);
    }
    posix_spawnattr_setsigmask(&attributes_, &no_signals);
    posix_spawnattr_setsigdefault(&attributes_, &default_signals);
    posix_spawnattr_setpgroup(&attributes_, 0);
    posix_spawnattr_setflags(&attributes_, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK |
                                               POSIX_SPAWN_SETSIGDEF);
  }
  ~SpawnAttributes() { posix_spawnattr_destroy(&attributes_); }
  SpawnAttributes(const SpawnAttributes&) = delete;
  SpawnAttributes& operator=(const SpawnAttributes&) = delete;
  const posix_spawnattr_t* get() const { return &attributes_; }

 private:
  posix_spawnattr_t attributes_{};
};

// The command line as started: metered, raygate-meter runs the program (joining `cgroup` first
// where there is one) and reports on its fd 3.
std::vector<std::string> spawned_argv(const ProcessSpec& spec, const std::filesystem::path& meter,
                                      const std::optional<MemoryCgroup>& cgroup) {
  std::vector<std::string> argv = spec.argv;
  if (!spec.metered) return argv;
  argv.insert(argv.begin(), {meter.string(), std::to_string(kMeterReportFd)});
  if (cgroup) argv.insert(argv.begin() + 1, {"--cgroup", cgroup->procs_file().string()});
  return argv;
}

ProcessResult spawn_failure(std::string error) {
  ProcessResult result;
  result.spawn_error = std::move(error);
  return result;
}

}  // namespace

Process Process::start(const ProcessSpec& spec) {
  Process p;
  p.spec_ = spec;
  throw_if_interrupted("before starting " + (spec.argv.empty() ? "a process" : spec.argv[0]));
  if (spec.argv.empty()) {
    p.early_result_ = spawn_failure("empty command");
    return p;
  }
  const std::filesystem::path meter = spec.metered ? meter_executable() : "";
  p.stdout_log_ = open_log(spec.stdout_path);
  p.stderr_log_ = spec.stderr_path == spec.stdout_path ? -1 : open_log(spec.stderr_path);
  ChildPipes pipes = open_child_pipes(spec.metered);
  const SpawnFileActions actions(spec, pipes);
  const SpawnAttributes attributes;
  if (spec.metered) p.cgroup_ = MemoryCgroup::create();
  std::vector<std::string> argv_strings = spawned_argv(spec, meter, p.cgroup_);
  std::vector<std::string> env_strings = build_environment(spec);
  std::vector<char*> argv = c_strings(argv_strings);
  std::vector<char*> envp = c_strings(env_strings);
  int spawn_status = 0;
  p.scope_ = std::make_unique<InterruptScope>();  // from here a signal stops this child
  {
    const std::lock_guard table(child_table_mutex());  // no sweep takes it before it is listed
    ScopedAffinity affinity(spec.cpu_affinity);
    p.started_ = Clock::now();
    spawn_status =
        ::posix_spawnp(&p.pid_, argv[0], actions.get(), attributes.get(), argv.data(), envp.data());
    if (spawn_status == 0) p.group_slot_ = register_child_group(p.pid_);
  }
  pipes.close_child_ends();
  p.meter_fd_ = pipes.meter[0];
  p.stdout_fd_ = pipes.out[0];
  p.stderr_fd_ = pipes.err[0];
  if (spawn_status != 0) {
    p.pid_ = -1;
    p.early_result_ = spawn_failure(spec.argv[0] + ": " + std::strerror(spawn_status));
    close_fd(p.stdout_fd_);
    close_fd(p.stderr_fd_);
    close_fd(p.meter_fd_);
    p.scope_.reset();
    return p;
  }
  p.pidfd_ = static_cast<int>(::syscall(SYS_pidfd_open, p.pid_, 0));
  return p;
}

Process::Process(Process&& other) noexcept
    : spec_(std::move(other.spec_)),
      pid_(std::exchange(other.pid_, -1)),
      pidfd_(std::exchange(other.pidfd_, -1)),
      stdout_fd_(std::exchange(other.stdout_fd_, -1)),
      stderr_fd_(std::exchange(other.stderr_fd_, -1)),
      stdout_log_(std::exchange(other.stdout_log_, -1)),
      stderr_log_(std::exchange(other.stderr_log_, -1)),
      meter_fd_(std::exchange(other.meter_fd_, -1)),
      cgroup_(std::move(other.cgroup_)),
      started_(other.started_),
      early_result_(std::move(other.early_result_)),
      reaped_(std::exchange(other.reaped_, true)),
      group_slot_(std::exchange(other.group_slot_, -1)),
      scope_(std::move(other.scope_)) {}

Process::~Process() {
  if (pid_ > 0 && !reaped_) {
    kill_group(SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  release_child_group(group_slot_);
  for (int* fd : {&pidfd_, &stdout_fd_, &stderr_fd_, &stdout_log_, &stderr_log_, &meter_fd_}) {
    close_fd(*fd);
  }
}

void Process::kill_group(int sig) const {
  if (pid_ > 0) ::kill(-pid_, sig);
}

namespace {
constexpr std::size_t kTailKept = 64 * 1024;  // what a truncated log ends with
}  // namespace

void Process::drain(int& fd, int log_fd, LogStream& stream, bool& truncated) {
  char buffer[1 << 15];
  const ssize_t n = ::read(fd, buffer, sizeof buffer);
  if (n < 0 && errno == EINTR) return;
  if (n <= 0) {
    close_fd(fd);
    return;
  }
  const auto size = static_cast<std::uint64_t>(n);
  if (log_fd < 0) return;
  const std::uint64_t room =
      spec_.log_limit_bytes > stream.written ? spec_.log_limit_bytes - stream.written : 0;
  const std::uint64_t keep = std::min(room, size);
  if (keep > 0 && ::write(log_fd, buffer, keep) > 0) stream.written += keep;
  if (keep == size) return;
  truncated = true;
  stream.dropped += size - keep;
  stream.tail.append(buffer + keep, size - keep);
  if (stream.tail.size() > 2 * kTailKept) stream.tail.erase(0, stream.tail.size() - kTailKept);
}

void Process::end_log(int log_fd, LogStream& stream) {
  if (log_fd < 0 || stream.dropped == 0) return;
  std::string_view tail = stream.tail;
  if (tail.size() > kTailKept) tail.remove_prefix(tail.size() - kTailKept);
  // From a line's start where a line starts in it, so the first line kept is whole; a tail that
  // is one line's end (400 MB of 'x' and then the time, with no newline between) stays whole.
  if (const std::size_t newline = tail.find('\n'); tail.size() < stream.dropped &&
                                                   newline != std::string_view::npos &&
                                                   newline + 1 < tail.size()) {
    tail.remove_prefix(newline + 1);
  }
  const std::string note =
      "\n[raygate: log truncated here: " + std::to_string(stream.dropped - tail.size()) +
      " bytes dropped; the last " + std::to_string(tail.size()) + " follow]\n";
  [[maybe_unused]] ssize_t ignored = ::write(log_fd, note.data(), note.size());
  ignored = ::write(log_fd, tail.data(), tail.size());
  stream = {};
}

bool Process::has_exited(bool block) const {
  for (;;) {
    siginfo_t info{};
    const int flags = WEXITED | WNOWAIT | (block ? 0 : WNOHANG);
    if (::waitid(P_PID, static_cast<id_t>(pid_), &info, flags) == 0) return info.si_pid == pid_;
    if (errno != EINTR) return true;  // not our child any more: nothing left to wait for
  }
}

void Process::reap(ProcessResult& result, Clock::time_point exited_at) {
  int status = 0;
  rusage usage{};
  pid_t r = -1;
  do {
    r = ::wait4(pid_, &status, 0, &usage);
  } while (r < 0 && errno == EINTR);
  reaped_ = true;
  if (r != pid_) return;
  result.wall_seconds = std::chrono::duration<double>(exited_at - started_).count();
  result.user_seconds = seconds_of(usage.ru_utime);
  result.system_seconds = seconds_of(usage.ru_stime);
  result.max_rss_kib = usage.ru_maxrss;
  if (WIFEXITED(status)) {
    if (result.outcome != ProcessOutcome::timed_out) result.outcome = ProcessOutcome::exited;
    result.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    if (result.outcome != ProcessOutcome::timed_out) result.outcome = ProcessOutcome::signaled;
    result.signal = WTERMSIG(status);
  }
}

// The meter wrote its line before it ended and the program cannot hold the pipe (close-on-exec),
// so the line is all there is to read. No line (the meter was killed, at a timeout): the times
// stay the meter's, which include the program's, and the peak is not the program's own.
void Process::read_meter_report(ProcessResult& result) {
  if (meter_fd_ < 0) return;
  std::string text;
  char buffer[256];
  for (;;) {
    const ssize_t n = ::read(meter_fd_, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
  }
  const MeterReport report = parse_meter_report(text);
  if (report.spawn_failed) {
    result = ProcessResult{};
    result.spawn_error = spec_.argv[0] + ": " + std::strerror(report.spawn_errno);
    return;
  }
  if (!report.has_usage) return;
  result.user_seconds = static_cast<double>(report.user_us) * 1e-6;
  result.system_seconds = static_cast<double>(report.system_us) * 1e-6;
  result.max_rss_kib = report.max_rss_kib;
  result.max_rss_own = true;
  result.peak_method = PeakMethod::largest_process;
  const std::optional<long> tree_kib =
      cgroup_ && report.joined_cgroup ? cgroup_->peak_kib() : std::nullopt;
  if (tree_kib) {
    result.max_rss_kib = *tree_kib;
    result.peak_method = cgroup_->method();
  }
  if (result.outcome != ProcessOutcome::timed_out) {
    result.wall_seconds = static_cast<double>(report.wall_ns) * 1e-9;  // without the meter's start
  }
}

// The child has exited and is a zombie, so its pid, and with it its group id, cannot have been
// reused: what is left in the group (a background process that closed its output) is killed
// before the reap. Then strays that left the group are swept.
void Process::finish(ProcessResult& result, Clock::time_point exited_at) {
  kill_group(SIGKILL);
  reap(result, exited_at);
  read_meter_report(result);
  cgroup_.reset();  // what is still in it is killed, and it is removed
  release_child_group(std::exchange(group_slot_, -1));
  sweep_stray_children();
  scope_.reset();
  for (int* fd : {&pidfd_, &stdout_fd_, &stderr_fd_, &stdout_log_, &stderr_log_, &meter_fd_}) {
    close_fd(*fd);
  }
  if (result.outcome == ProcessOutcome::timed_out && result.signal == 0) result.signal = SIGTERM;
  throw_if_interrupted("while running " + spec_.argv[0]);
}

ProcessResult Process::wait() {
  if (early_result_) return *early_result_;
  ProcessResult result;
  result.outcome = ProcessOutcome::exited;
  LogStream out_stream;
  LogStream err_stream;
  const int err_log = stderr_log_ >= 0 ? stderr_log_ : stdout_log_;
  const bool has_timeout = spec_.timeout.count() > 0;
  const auto deadline = started_ + spec_.timeout;
  bool exited = false;  // the child has ended (a zombie until finish() reaps it)
  Clock::time_point exited_at;
  std::optional<Clock::time_point> kill_at;
  std::optional<Clock::time_point>
      pipes_deadline;  // after exit, how long grandchildren may hold pipes

  while (!exited || stdout_fd_ >= 0 || stderr_fd_ >= 0) {
    const auto now = Clock::now();
    if (!exited && !kill_at && interrupt_signal() != 0) {
      kill_group(SIGTERM);  // let a build tool clean up, briefly: the user is waiting
      kill_at = now + std::min(spec_.kill_grace, std::chrono::milliseconds(2000));
    } else if (!exited && has_timeout && !kill_at && now >= deadline) {
      result.outcome = ProcessOutcome::timed_out;
      kill_group(SIGTERM);
      kill_at = now + spec_.kill_grace;
    }
    if (kill_at && !exited && now >= *kill_at) kill_group(SIGKILL);
    if (exited && !pipes_deadline) pipes_deadline = now + std::chrono::milliseconds(200);
    if (pipes_deadline && now >= *pipes_deadline) break;  // strays still hold our pipes
    pollfd fds[4] = {{stdout_fd_, POLLIN, 0},
                     {stderr_fd_, POLLIN, 0},
                     {exited ? -1 : pidfd_, POLLIN, 0},
                     {exited || kill_at ? -1 : interrupt_fd(), POLLIN, 0}};
    int wait_ms = 50;  // also bounds the reaping latency when pidfd_open is unavailable
    if (has_timeout && !kill_at && !exited) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - now);
      wait_ms = static_cast<int>(std::clamp<long>(left.count() + 1, 0, wait_ms));
    }
    if (pidfd_ >= 0 && !has_timeout && !kill_at && !pipes_deadline) wait_ms = -1;
    const int ready = ::poll(fds, 4, wait_ms);
    if (ready < 0 && errno != EINTR) break;
    if (fds[0].revents != 0) drain(stdout_fd_, stdout_log_, out_stream, result.stdout_truncated);
    if (fds[1].revents != 0) drain(stderr_fd_, err_log, err_stream, result.stderr_truncated);
    if (!exited && has_exited(false)) {
      exited = true;
      exited_at = Clock::now();
    }
  }
  if (!exited) {
    has_exited(true);
    exited_at = Clock::now();
  }
  end_log(stdout_log_, out_stream);
  end_log(err_log, err_stream);
  finish(result, exited_at);
  return result;
}

ProcessResult run_process(const ProcessSpec& spec) {
  Process p = Process::start(spec);
  return p.wait();
}

std::string log_tail(const std::filesystem::path& path, int max_lines) {
  std::ifstream in(path);
  if (!in) return {};
  std::deque<std::string> lines;
  std::string line;
  while (std::getline(in, line)) {
    lines.push_back(line);
    if (static_cast<int>(lines.size()) > max_lines) lines.pop_front();
  }
  std::string out;
  for (const std::string& l : lines) out += l + "\n";
  return out;
}

std::vector<int> allowed_cpu_list() {
  cpu_set_t set;
  CPU_ZERO(&set);
  std::vector<int> cpus;
  if (sched_getaffinity(0, sizeof set, &set) != 0) return cpus;
  for (int cpu = 0; cpu < CPU_SETSIZE; ++cpu) {
    if (CPU_ISSET(cpu, &set)) cpus.push_back(cpu);
  }
  return cpus;
}

}  // namespace raygate

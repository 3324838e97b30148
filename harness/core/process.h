// One child process, owned from spawn to reaping (like ninja's Subprocess): argv without a
// shell, a controlled environment, its own process group, a timeout that sends SIGTERM and then
// SIGKILL to the whole group, stdout/stderr drained into size-bounded log files, and the
// resources wait4 reports. A tracer that crashes or hangs is a result here, not an exception.
// Nothing the child started outlives it: what is left in its group when it exits is killed,
// and strays that left the group are swept (core/strays.h). SIGINT, SIGTERM or SIGHUP to
// raygate (core/interrupt.h) kills the group too and throws Interrupted.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/memory_cgroup.h"

namespace raygate {

class InterruptScope;

struct ProcessSpec {
  std::vector<std::string> argv;            // argv[0] is looked up in PATH when it has no '/'
  std::filesystem::path working_directory;  // empty: the caller's
  bool inherit_environment = true;
  std::map<std::string, std::string> environment;  // set (or override) these variables
  std::filesystem::path stdin_path;                // empty: /dev/null
  std::filesystem::path stdout_path;               // empty: discarded
  std::filesystem::path stderr_path;           // empty: discarded; may equal stdout_path (merged)
  std::uint64_t log_limit_bytes = 8u << 20;    // per stream; the rest is drained and dropped
  std::chrono::milliseconds timeout{0};        // 0: none
  std::chrono::milliseconds kill_grace{2000};  // SIGTERM to SIGKILL (at most 2 s when interrupted)
  std::vector<int> cpu_affinity;               // CPUs to pin to; empty: inherit
  // Start it through raygate-meter (core/process_meter_main.cpp), so that max_rss_kib and the
  // times are the program's own (and its waited-for children's), not raygate's seen through
  // fork. pid() is then the meter's, which forwards single-process signals to the program.
  // Where a memory cgroup can be made (core/memory_cgroup.h), the peak is the whole process
  // tree's at once; else its largest process's (ProcessResult::peak_method says which).
  bool metered = false;
};

enum class ProcessOutcome {
  exited,        // ran to completion; see exit_code
  signaled,      // killed by a signal it did not get from us (a crash)
  timed_out,     // we stopped it at the timeout
  spawn_failed,  // never ran (no such program, not executable, bad working directory)
};

// What a process used: its times and its peak memory. A timed run's record keeps it as the
// process reported it (runner/run_record.h).
struct ProcessUsage {
  double wall_seconds = 0.0;
  double user_seconds = 0.0;
  double system_seconds = 0.0;
  long max_rss_kib = 0;  // peak resident memory (KiB); raygate's own unless the spec was metered
  // max_rss_kib is the program's own (metered, and the meter reported): only such peaks are
  // judged, raygate's seen through fork are not the program's.
  bool max_rss_own = false;
  // How an own peak was measured: the whole process tree at once (a memory cgroup), or its
  // largest single process (where no cgroup could be made).
  PeakMethod peak_method = PeakMethod::raygate_process;

  double cpu_seconds() const { return user_seconds + system_seconds; }
  bool operator==(const ProcessUsage&) const = default;
};

struct ProcessResult : ProcessUsage {
  ProcessOutcome outcome = ProcessOutcome::spawn_failed;
  int exit_code = -1;  // when exited
  int signal = 0;      // when signaled or timed_out
  bool stdout_truncated = false;
  bool stderr_truncated = false;
  std::string spawn_error;

  bool succeeded() const { return outcome == ProcessOutcome::exited && exit_code == 0; }
  // "exited with status 3", "killed by SIGSEGV", "timed out after 10 s", ...
  std::string describe() const;
};

class Process {
 public:
  // Starts the child. Never throws for a program that cannot run: wait() reports spawn_failed.
  // Throws InfraError if the log files cannot be created, Interrupted if raygate was asked to
  // stop (then nothing is started).
  static Process start(const ProcessSpec& spec);

  Process(Process&& other) noexcept;
  Process& operator=(Process&&) = delete;
  Process(const Process&) = delete;
  ~Process();  // a still-running child's group is killed and reaped

  // Drains output and waits for the child (honouring the timeout); call once. Throws
  // Interrupted once SIGINT, SIGTERM or SIGHUP arrived, after killing and reaping the child's
  // group, even if the child ended by itself meanwhile: nothing that ran then counts.
  ProcessResult wait();
  pid_t pid() const { return pid_; }

 private:
  Process() = default;
  // One output stream's log: what was written, and past log_limit_bytes what was dropped, of
  // which the last bytes are kept to end the log (a tracer prints its time last: a sweep's
  // 400 MB of output lost it, and the run was said to print no time).
  struct LogStream {
    std::uint64_t written = 0;
    std::uint64_t dropped = 0;
    std::string tail;
  };
  void drain(int& fd, int log_fd, LogStream& stream, bool& truncated);
  static void end_log(int log_fd, LogStream& stream);
  void kill_group(int sig) const;
  bool has_exited(bool block) const;  // leaves the child a zombie, so its pid stays ours
  void reap(ProcessResult& result, std::chrono::steady_clock::time_point exited_at);
  void finish(ProcessResult& result, std::chrono::steady_clock::time_point exited_at);
  void read_meter_report(ProcessResult& result);

  ProcessSpec spec_;
  pid_t pid_ = -1;
  int pidfd_ = -1;
  int stdout_fd_ = -1;
  int stderr_fd_ = -1;
  int stdout_log_ = -1;
  int stderr_log_ = -1;
  int meter_fd_ = -1;                   // read end of raygate-meter's report, when metered
  std::optional<MemoryCgroup> cgroup_;  // the metered tree's own, where one can be made
  std::chrono::steady_clock::time_point started_;
  std::optional<ProcessResult> early_result_;  // set when spawning failed
  bool reaped_ = false;
  int group_slot_ = -1;                    // in the table of live children (core/interrupt.h)
  std::unique_ptr<InterruptScope> scope_;  // a signal is acted on while the child lives
};

// Where raygate-meter is: beside the running executable. InfraError (exit 3) when it is not.
std::filesystem::path meter_executable();

// Starts, waits, returns the result.
ProcessResult run_process(const ProcessSpec& spec);

// The CPUs this process may run on (its affinity mask), in ascending order.
std::vector<int> allowed_cpu_list();

// The last `max_lines` lines of a log file (for error messages); empty if unreadable.
std::string log_tail(const std::filesystem::path& path, int max_lines = 20);

}  // namespace raygate

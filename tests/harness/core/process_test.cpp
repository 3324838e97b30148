// Process: exit statuses, crashes, timeouts (whole group), bounded logs, environment, cwd, stdin.
#include "core/process.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <fstream>

#include "core/fs.h"

namespace raygate {
namespace {

ProcessSpec shell(const std::string& script, const TempDir& dir) {
  ProcessSpec spec;
  spec.argv = {"/bin/sh", "-c", script};
  spec.stdout_path = dir.path() / "out.log";
  spec.stderr_path = dir.path() / "err.log";
  return spec;
}

TEST(Process, ReportsExitStatusAndCapturesBothStreams) {
  TempDir dir;
  const ProcessResult r = run_process(shell("echo hello; echo oops >&2; exit 3", dir));
  EXPECT_EQ(r.outcome, ProcessOutcome::exited);
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_FALSE(r.succeeded());
  EXPECT_EQ(read_file(dir.path() / "out.log"), "hello\n");
  EXPECT_EQ(read_file(dir.path() / "err.log"), "oops\n");
  EXPECT_EQ(r.describe(), "exited with status 3");
}

TEST(Process, MergesStreamsWhenBothGoToOneFile) {
  TempDir dir;
  ProcessSpec spec = shell("echo a; echo b >&2", dir);
  spec.stderr_path = spec.stdout_path;
  ASSERT_TRUE(run_process(spec).succeeded());
  const std::string log = read_file(spec.stdout_path);
  EXPECT_NE(log.find("a\n"), std::string::npos);
  EXPECT_NE(log.find("b\n"), std::string::npos);
}

TEST(Process, ACrashIsASignalNotAnException) {
  TempDir dir;
  const ProcessResult r = run_process(shell("kill -SEGV $$", dir));
  EXPECT_EQ(r.outcome, ProcessOutcome::signaled);
  EXPECT_EQ(r.signal, SIGSEGV);
  EXPECT_NE(r.describe().find("SEGV"), std::string::npos);
}

TEST(Process, MissingProgramIsSpawnFailure) {
  TempDir dir;
  ProcessSpec spec;
  spec.argv = {"/nonexistent/tracer", "x"};
  const ProcessResult r = run_process(spec);
  EXPECT_EQ(r.outcome, ProcessOutcome::spawn_failed);
  EXPECT_NE(r.describe().find("/nonexistent/tracer"), std::string::npos);
}

TEST(Process, TimeoutKillsTheWholeProcessGroup) {
  TempDir dir;
  // The child starts a grandchild that would outlive it; both must be gone after the timeout.
  ProcessSpec spec =
      shell("sleep 30 & echo $! > " + (dir.path() / "grandchild").string() + "; sleep 30", dir);
  spec.timeout = std::chrono::milliseconds(300);
  spec.kill_grace = std::chrono::milliseconds(200);
  const ProcessResult r = run_process(spec);
  EXPECT_EQ(r.outcome, ProcessOutcome::timed_out);
  EXPECT_LT(r.wall_seconds, 5.0);
  const int grandchild = std::stoi(read_file(dir.path() / "grandchild"));
  // Reaped by init eventually; kill(pid, 0) fails once it is gone or a zombie of init's.
  bool gone = false;
  for (int i = 0; i < 100 && !gone; ++i) {
    std::ifstream stat("/proc/" + std::to_string(grandchild) + "/stat");
    std::string pid, comm, state;
    gone = !(stat >> pid >> comm >> state) || state == "Z";
    if (!gone) usleep(20000);
  }
  EXPECT_TRUE(gone);
}

TEST(Process, IgnoringSigtermStillEndsAfterTheGrace) {
  TempDir dir;
  ProcessSpec spec = shell("trap '' TERM; while :; do :; done", dir);
  // A second for the shell to reach its trap even on a loaded runner (a TERM before it would
  // end the test's child the easy way).
  spec.timeout = std::chrono::milliseconds(1000);
  spec.kill_grace = std::chrono::milliseconds(200);
  const ProcessResult r = run_process(spec);
  EXPECT_EQ(r.outcome, ProcessOutcome::timed_out);
  EXPECT_LT(r.wall_seconds, 6.0);
  // It shrugged off TERM and was ended by KILL after the grace. (Its CPU seconds, asserted here
  // before, depend on how busy the machine is: at load 12 a spinning child got under 0.1 s.)
  EXPECT_EQ(r.signal, SIGKILL);
  // Said, so the seconds past the limit (the grace) do not read as a wrong clock (a sweep).
  EXPECT_NE(r.describe().find("(it ignored SIGTERM at the limit and was killed)"),
            std::string::npos)
      << r.describe();
}

// The log keeps its start and, after a note, its last 64 KiB from a line's start: a tracer
// prints its time last (a sweep's 400 MB of output lost it, and the run "printed no time").
TEST(Process, LogsAreBoundedButTheChildIsNotBlockedAndTheEndIsKept) {
  TempDir dir;
  ProcessSpec spec =
      shell("head -c 1000000 /dev/zero | tr '\\0' x; echo; echo 'render time: 1.5 s'", dir);
  spec.log_limit_bytes = 1000;
  const ProcessResult r = run_process(spec);
  ASSERT_TRUE(r.succeeded());
  EXPECT_TRUE(r.stdout_truncated);
  const std::string log = read_file(spec.stdout_path);
  EXPECT_EQ(log.substr(0, 1000), std::string(1000, 'x'));
  EXPECT_NE(log.find("[raygate: log truncated here: 999001 bytes dropped; the last 19 follow]\n"),
            std::string::npos)
      << log.substr(1000, 200);
  EXPECT_TRUE(log.ends_with("\nrender time: 1.5 s\n")) << log.substr(log.size() - 100);
  EXPECT_LT(log.size(), 1100u);
}

// The time printed on the same line as the flood (no newline between): the tail stays whole.
TEST(Process, ATruncatedLogKeepsTheEndOfAnEndlessLine) {
  TempDir dir;
  ProcessSpec spec = shell("head -c 1000000 /dev/zero | tr '\\0' x; echo ' 1.5 s'", dir);
  spec.log_limit_bytes = 1000;
  ASSERT_TRUE(run_process(spec).succeeded());
  const std::string log = read_file(spec.stdout_path);
  EXPECT_NE(log.find("bytes dropped; the last 65536 follow]\n"), std::string::npos);
  EXPECT_TRUE(log.ends_with("xxx 1.5 s\n")) << log.substr(log.size() - 100);
}

TEST(Process, EnvironmentWorkingDirectoryAndStdin) {
  TempDir dir;
  std::filesystem::create_directory(dir.path() / "work");
  { std::ofstream(dir.path() / "input.txt") << "from stdin\n"; }
  ProcessSpec spec = shell("echo \"$RAYGATE_TEST_VAR\"; pwd; cat", dir);
  spec.environment["RAYGATE_TEST_VAR"] = "value with spaces";
  spec.working_directory = dir.path() / "work";
  spec.stdin_path = dir.path() / "input.txt";
  ASSERT_TRUE(run_process(spec).succeeded());
  EXPECT_EQ(read_file(spec.stdout_path),
            "value with spaces\n" + (dir.path() / "work").string() + "\nfrom stdin\n");
}

TEST(Process, ClearedEnvironmentHasOnlyWhatWasSet) {
  TempDir dir;
  ProcessSpec spec = shell("env", dir);
  spec.argv[0] = "/bin/sh";
  spec.inherit_environment = false;
  spec.environment["ONLY"] = "1";
  ASSERT_TRUE(run_process(spec).succeeded());
  const std::string env = read_file(spec.stdout_path);
  EXPECT_NE(env.find("ONLY=1"), std::string::npos);
  EXPECT_EQ(env.find("HOME="), std::string::npos);
}

TEST(Process, MeasuresCpuTimeOfABusyChild) {
  TempDir dir;
  const ProcessResult r =
      run_process(shell("i=0; while [ $i -lt 200000 ]; do i=$((i+1)); done", dir));
  ASSERT_TRUE(r.succeeded());
  EXPECT_GT(r.user_seconds, 0.01);
  EXPECT_GE(r.wall_seconds, r.user_seconds * 0.5);
  EXPECT_GT(r.max_rss_kib, 0);
}

TEST(Process, PinsToTheRequestedCpu) {
  TempDir dir;
  ProcessSpec spec = shell("grep Cpus_allowed_list /proc/self/status", dir);
  spec.cpu_affinity = {0};
  ASSERT_TRUE(run_process(spec).succeeded());
  EXPECT_NE(read_file(spec.stdout_path).find("Cpus_allowed_list:\t0\n"), std::string::npos);
}

TEST(Process, LogTailKeepsTheLastLines) {
  TempDir dir;
  ProcessSpec spec = shell("for i in 1 2 3 4 5; do echo line$i; done", dir);
  ASSERT_TRUE(run_process(spec).succeeded());
  EXPECT_EQ(log_tail(spec.stdout_path, 2), "line4\nline5\n");
}

}  // namespace
}  // namespace raygate

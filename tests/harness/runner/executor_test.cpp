// SystemExecutor with real processes: run_together starts every spec at once, and each process
// is timed and drained on its own, so a quick one beside a slow one (the duet schedule) is not
// charged the slow one's time, nor blocked on a full output pipe while the other runs.
#include "runner/executor.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <thread>

#include "core/fs.h"
#include "core/interrupt.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;

ProcessSpec shell(const std::string& script, const fs::path& log) {
  ProcessSpec spec;
  spec.argv = {"/bin/sh", "-c", script};
  spec.stdout_path = log;
  spec.stderr_path = log;
  spec.timeout = std::chrono::seconds(30);
  return spec;
}

TEST(SystemExecutor, RunTogetherStartsEverySpecAtOnce) {
  TempDir dir;
  SteadyClock clock;
  SystemExecutor executor;
  const double start = clock.now_seconds();
  const std::vector<ProcessResult> results = executor.run_together(
      {shell("sleep 0.6", dir.path() / "a.log"), shell("sleep 0.6", dir.path() / "b.log")});
  const double elapsed = clock.now_seconds() - start;
  ASSERT_EQ(results.size(), 2u);
  for (const ProcessResult& r : results) EXPECT_TRUE(r.succeeded()) << r.describe();
  EXPECT_LT(elapsed, 1.1);  // not one after the other
}

TEST(SystemExecutor, QuickProcessBesideASlowOneIsTimedByItsOwnEnd) {
  TempDir dir;
  SystemExecutor executor;
  const std::vector<ProcessResult> results = executor.run_together(
      {shell("sleep 1.5", dir.path() / "slow.log"), shell("sleep 0.1", dir.path() / "quick.log")});
  EXPECT_GT(results[0].wall_seconds, 1.4);
  EXPECT_LT(results[1].wall_seconds, 0.9) << "the quick process was charged the slow one's time";
}

TEST(SystemExecutor, ChattyProcessIsDrainedWhileTheOtherRuns) {
  TempDir dir;
  SystemExecutor executor;
  // 4 MB of output: far more than a pipe holds, so it blocks unless it is read as it comes.
  const std::vector<ProcessResult> results = executor.run_together(
      {shell("sleep 1.5", dir.path() / "slow.log"),
       shell("head -c 4000000 /dev/zero | tr '\\0' x", dir.path() / "chatty.log")});
  ASSERT_TRUE(results[1].succeeded()) << results[1].describe();
  EXPECT_LT(results[1].wall_seconds, 0.9);
  EXPECT_EQ(fs::file_size(dir.path() / "chatty.log"), 4000000u);
}

TEST(SystemExecutor, RunTogetherKeepsTheOrderOfTheSpecs) {
  TempDir dir;
  SystemExecutor executor;
  const std::vector<ProcessResult> results = executor.run_together(
      {shell("exit 3", dir.path() / "a.log"), shell("sleep 0.2; exit 5", dir.path() / "b.log")});
  EXPECT_EQ(results[0].exit_code, 3);
  EXPECT_EQ(results[1].exit_code, 5);
}

// SIGINT during a duet: both waiting threads wake (the signal reaches one thread only; the
// self-pipe wakes every poller), both children are stopped, and Interrupted comes out.
TEST(SystemExecutor, InterruptStopsEveryProcessOfARunTogether) {
  install_interrupt_handlers();
  TempDir dir;
  SystemExecutor executor;
  const fs::path a = dir.path() / "a.log";
  const fs::path b = dir.path() / "b.log";
  std::thread stopper([&] {
    auto up = [](const fs::path& log) { return fs::exists(log) && fs::file_size(log) > 0; };
    for (int i = 0; i < 1000 && !(up(a) && up(b)); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ::kill(::getpid(), SIGINT);  // both children run: the handler only records it
  });
  const auto started = std::chrono::steady_clock::now();
  EXPECT_THROW(
      executor.run_together({shell("echo up; sleep 20", a), shell("echo up; sleep 20", b)}),
      Interrupted);
  stopper.join();
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(5));
  clear_interrupt_for_testing();
}

}  // namespace
}  // namespace raygate

// Nothing a child starts outlives it: what is left in its group when it exits is killed, a
// `setsid` grandchild is swept (raygate as subreaper), and SIGINT or SIGTERM to raygate kills
// the child's whole group and throws Interrupted (130 / 143).
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "core/fs.h"
#include "core/interrupt.h"
#include "core/process.h"
#include "core/strays.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

ProcessSpec shell(const std::string& script, const TempDir& dir) {
  ProcessSpec spec;
  spec.argv = {"/bin/sh", "-c", script};
  spec.stdout_path = dir.path() / "out.log";
  spec.stderr_path = spec.stdout_path;
  return spec;
}

// Running (not gone, not a zombie waiting for whoever inherited it).
bool alive(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(stat, text)) return false;
  const std::size_t close = text.rfind(')');
  return close != std::string::npos && close + 2 < text.size() && text[close + 2] != 'Z';
}

// Waits until `pid` is no longer alive (at most 5 s): a killed process takes a moment to die.
bool ends(pid_t pid) {
  for (int i = 0; i < 250 && alive(pid); ++i) std::this_thread::sleep_for(20ms);
  return !alive(pid);
}

pid_t pid_in(const fs::path& file) {
  for (int i = 0; i < 500 && (!fs::exists(file) || fs::file_size(file) == 0); ++i) {
    std::this_thread::sleep_for(10ms);
  }
  return static_cast<pid_t>(std::stoi(read_file(file)));
}

TEST(ProcessCleanup, WhatIsLeftInTheGroupIsKilledWhenTheChildExits) {
  TempDir dir;
  // A background process that closed its output: it does not even hold the log pipe open.
  const fs::path grandchild = dir.path() / "grandchild";
  const ProcessResult r = run_process(
      shell("sleep 30 </dev/null >/dev/null 2>&1 & echo $! > " + grandchild.string(), dir));
  ASSERT_TRUE(r.succeeded());
  EXPECT_LT(r.wall_seconds, 5.0);
  EXPECT_TRUE(ends(pid_in(grandchild)));
}

TEST(ProcessCleanup, SetsidGrandchildIsSweptWhenRaygateIsTheSubreaper) {
  ASSERT_TRUE(become_subreaper());
  TempDir dir;
  // setsid leaves the child's process group and session: killing the group cannot reach it.
  const fs::path stray = dir.path() / "stray";
  const ProcessResult r = run_process(
      shell("setsid sleep 30 </dev/null >/dev/null 2>&1 & echo $! > " + stray.string(), dir));
  ASSERT_TRUE(r.succeeded());
  const pid_t pid = pid_in(stray);
  EXPECT_TRUE(ends(pid));
  EXPECT_FALSE(fs::exists("/proc/" + std::to_string(pid))) << "swept, and reaped by us";
}

TEST(ProcessCleanup, SweepLeavesARunningSiblingAlone) {
  ASSERT_TRUE(become_subreaper());
  TempDir dir;
  TempDir other_dir;
  Process sibling = Process::start(shell("sleep 30", other_dir));
  ASSERT_TRUE(run_process(shell("true", dir)).succeeded());  // ends and sweeps
  EXPECT_TRUE(alive(sibling.pid())) << "a child raygate started is not a stray";
}

class ProcessInterrupt : public ::testing::Test {
 protected:
  ProcessInterrupt() { install_interrupt_handlers(); }
  ~ProcessInterrupt() override { clear_interrupt_for_testing(); }

  // Runs a child with a grandchild; once both are up, sends `sig` to this process and checks
  // that wait() throws promptly and both are gone.
  void interrupt_with(int sig) {
    TempDir dir;
    const fs::path child = dir.path() / "child";
    const fs::path grandchild = dir.path() / "grandchild";
    ProcessSpec spec = shell(
        "sleep 30 & echo $! > " + grandchild.string() + "; echo $$ > " + child.string() + "; wait",
        dir);
    Process p = Process::start(spec);
    const pid_t child_pid = pid_in(child);
    const pid_t grandchild_pid = pid_in(grandchild);
    const auto sent = std::chrono::steady_clock::now();
    ::kill(::getpid(), sig);  // as Ctrl-C or `kill` would; the handler only records it
    try {
      p.wait();
      ADD_FAILURE() << "wait() returned after " << signal_name(sig);
    } catch (const Interrupted& e) {
      EXPECT_EQ(e.signal(), sig);
      EXPECT_EQ(to_int(e.code()), 128 + sig);
      EXPECT_NE(std::string(e.what()).find("interrupted by " + signal_name(sig)), std::string::npos)
          << e.what();
    }
    EXPECT_LT(std::chrono::steady_clock::now() - sent, 3s);
    EXPECT_TRUE(ends(child_pid));
    EXPECT_TRUE(ends(grandchild_pid));
  }
};

TEST_F(ProcessInterrupt, SigintKillsTheWholeGroupAndThrows) { interrupt_with(SIGINT); }

TEST_F(ProcessInterrupt, SigtermKillsTheWholeGroupAndThrows) { interrupt_with(SIGTERM); }

// A closed terminal or ssh session: the tracer must not outlive it, hung, forever.
TEST_F(ProcessInterrupt, SighupKillsTheWholeGroupAndThrows) {
  struct sigaction current {};
  ::sigaction(SIGHUP, nullptr, &current);
  if (current.sa_handler == SIG_IGN) GTEST_SKIP() << "started under nohup: SIGHUP stays ignored";
  interrupt_with(SIGHUP);
}

TEST_F(ProcessInterrupt, AChildThatEndsCleanlyOnTheSignalStillDoesNotCount) {
  TempDir dir;
  const fs::path ready = dir.path() / "ready";
  Process p = Process::start(shell(
      "trap 'exit 0' TERM; echo $$ > " + ready.string() + "; while :; do sleep 0.05; done", dir));
  pid_in(ready);
  request_interrupt(SIGINT);
  EXPECT_THROW(p.wait(), Interrupted);
}

TEST_F(ProcessInterrupt, NothingStartsOnceAStopWasRequested) {
  TempDir dir;
  request_interrupt(SIGTERM);
  const fs::path marker = dir.path() / "ran";
  EXPECT_THROW(Process::start(shell("touch " + marker.string(), dir)), Interrupted);
  std::this_thread::sleep_for(100ms);
  EXPECT_FALSE(fs::exists(marker));
}

}  // namespace
}  // namespace raygate

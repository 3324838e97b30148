// Ctrl-C (SIGINT), SIGTERM, SIGHUP (the terminal or ssh session closed) and Ctrl-\ (SIGQUIT)
// while raygate runs a tracer or a build step. Children run in their own process groups, so the
// terminal's signal reaches raygate only; raygate must stop them, or a hung tracer outlives the session forever.
// The handler only records the signal (an atomic flag and a byte on a self-pipe, both
// async-signal-safe). Process::wait sees it, kills its child's group and throws Interrupted,
// which travels up through the measuring code (that writes its document, complete: false) to
// cli/main.cpp, which exits 128 + the signal: 129 (SIGHUP), 130 (SIGINT), 131 (SIGQUIT) or 143
// (SIGTERM).
//
// A signal counts as a request to stop only while someone will act on it: while a child runs
// or an InterruptScope is open. Otherwise, and on a second signal, the handler kills every live
// child group and ends raygate at once with the signal's default action. Two repeats are not a
// second signal: a SIGHUP after a SIGHUP (a hang-up is delivered more than once; nobody pressed
// anything), and the same signal again within kRepeatWindowNanoseconds of the first (GNU timeout
// and CI runners signal raygate and then its process group: one request, delivered twice).
#pragma once

#include <sys/types.h>

#include <csignal>
#include <cstdint>
#include <string>

#include "core/error.h"

namespace raygate {

// Thrown once SIGINT, SIGTERM, SIGHUP or SIGQUIT arrived; code() is 128 + the signal. what() says what
// was kept.
class Interrupted : public Error {
 public:
  Interrupted(int signal, const std::string& message);
  int signal() const { return signal_; }

 private:
  int signal_;
};

// How long after the first signal the same signal again is taken as the same request. The two
// copies a wrapper sends arrive microseconds apart, but each is handled only when raygate is
// next scheduled: on a loaded CI machine, at nice 19, that can be tens to hundreds of
// milliseconds. A person who means "now" presses again; a press after a second still ends
// raygate at once, and a second is well inside the 2 s the first request gives a child to stop.
inline constexpr std::int64_t kRepeatWindowNanoseconds = 1'000'000'000;

// What the handler does with a stop signal.
enum class StopAction {
  record,   // the first request: recorded for the code that stops gracefully
  ignore,   // a repeat of the recorded request (see above)
  end_now,  // the escape: kill the children's groups and die of the signal
};

// The handler's decision, apart from the handler so a test can give it any clock: `signal`
// arrives at `now_ns` (CLOCK_MONOTONIC); `recorded` is the signal recorded before (0: none) at
// `recorded_ns`; `someone_acts` whether an InterruptScope is open.
constexpr StopAction decide_stop(int signal, std::int64_t now_ns, int recorded,
                                 std::int64_t recorded_ns, bool someone_acts) {
  if (recorded == 0) return someone_acts ? StopAction::record : StopAction::end_now;
  if (signal != recorded) return StopAction::end_now;
  if (signal == SIGHUP) return StopAction::ignore;
  const std::int64_t since_ns = now_ns - recorded_ns;
  return since_ns >= 0 && since_ns < kRepeatWindowNanoseconds ? StopAction::ignore
                                                              : StopAction::end_now;
}

// Installs the SIGINT, SIGTERM, SIGHUP and SIGQUIT handlers and creates the self-pipe. Call once, early
// in main; calling again does nothing. A signal ignored when raygate started (nohup, a
// background job's SIGINT) stays ignored.
void install_interrupt_handlers();

// The signal that asked raygate to stop, or 0.
int interrupt_signal();

// Becomes readable once a stop was requested (never drained, so every poller wakes); -1 before
// install_interrupt_handlers().
int interrupt_fd();

// What the handler does on the first signal; tests call it directly.
void request_interrupt(int signal);

// Throws Interrupted ("interrupted by SIGINT <doing>") if a stop was requested.
void throw_if_interrupted(const std::string& doing);

// "SIGINT", "SIGTERM", "SIGHUP".
std::string signal_name(int signal);

// Forgets a requested stop (tests only: raygate never resumes after one).
void clear_interrupt_for_testing();

// While one is open, a signal is recorded for the code below to act on (write what it has,
// then stop) instead of ending raygate at once. Process holds one while its child lives.
class InterruptScope {
 public:
  InterruptScope();
  ~InterruptScope();
  InterruptScope(const InterruptScope&) = delete;
  InterruptScope& operator=(const InterruptScope&) = delete;
};

// The process groups of live children, for the handler to kill on a second signal. Returns a
// slot for release_child_group (-1 if the table is full: that child is then only not killed by
// a second signal).
int register_child_group(pid_t group);
void release_child_group(int slot);
// Whether `pid` is a child raygate started and has not reaped yet.
bool is_registered_child(pid_t pid);

}  // namespace raygate

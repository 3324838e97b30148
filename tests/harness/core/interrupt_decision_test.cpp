// core/interrupt's decision on a stop signal, on a made-up clock: the first is recorded while
// someone acts on it, the same signal again within the repeat window is the same request (GNU
// timeout signals raygate and then its process group), and a later one, or another signal, is
// the escape. A repeated SIGHUP never is.
#include <gtest/gtest.h>

#include <csignal>
#include <cstdint>

#include "core/interrupt.h"

namespace raygate {
namespace {

constexpr std::int64_t kMillisecond = 1'000'000;
constexpr std::int64_t kFirstAt = 5'000 * kMillisecond;  // any point on the monotonic clock

TEST(StopDecision, TheFirstSignalIsRecordedOnlyWhileSomeoneActsOnIt) {
  for (const int sig : {SIGINT, SIGTERM, SIGHUP}) {
    EXPECT_EQ(decide_stop(sig, kFirstAt, 0, 0, true), StopAction::record);
    EXPECT_EQ(decide_stop(sig, kFirstAt, 0, 0, false), StopAction::end_now);
  }
}

TEST(StopDecision, TheSameSignalWithinTheWindowIsTheSameRequest) {
  for (const int sig : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(signal_name(sig));
    // timeout's second copy: microseconds later, or late when raygate was not scheduled.
    for (const std::int64_t after : {std::int64_t{0}, std::int64_t{20'000}, 300 * kMillisecond,
                                     kRepeatWindowNanoseconds - 1}) {
      EXPECT_EQ(decide_stop(sig, kFirstAt + after, sig, kFirstAt, true), StopAction::ignore)
          << after << " ns after the first";
      // The scope may have closed meanwhile (the document being written): still the same one.
      EXPECT_EQ(decide_stop(sig, kFirstAt + after, sig, kFirstAt, false), StopAction::ignore);
    }
  }
}

TEST(StopDecision, ADeliberateSecondSignalLaterIsTheEscape) {
  for (const int sig : {SIGINT, SIGTERM}) {
    SCOPED_TRACE(signal_name(sig));
    for (const std::int64_t after :
         {kRepeatWindowNanoseconds, 1'500 * kMillisecond, 60'000 * kMillisecond}) {
      EXPECT_EQ(decide_stop(sig, kFirstAt + after, sig, kFirstAt, true), StopAction::end_now)
          << after << " ns after the first";
    }
  }
  // A clock that seems to run backwards is not taken as a repeat.
  EXPECT_EQ(decide_stop(SIGINT, kFirstAt - 1, SIGINT, kFirstAt, true), StopAction::end_now);
}

TEST(StopDecision, ADifferentSignalIsTheEscapeAtOnce) {
  EXPECT_EQ(decide_stop(SIGTERM, kFirstAt + 1, SIGINT, kFirstAt, true), StopAction::end_now);
  EXPECT_EQ(decide_stop(SIGINT, kFirstAt + 1, SIGTERM, kFirstAt, true), StopAction::end_now);
  EXPECT_EQ(decide_stop(SIGINT, kFirstAt + 1, SIGHUP, kFirstAt, true), StopAction::end_now);
  EXPECT_EQ(decide_stop(SIGHUP, kFirstAt + 1, SIGTERM, kFirstAt, true), StopAction::end_now);
}

TEST(StopDecision, ARepeatedHangUpIsNeverTheEscape) {
  for (const std::int64_t after :
       {std::int64_t{1}, 2 * kRepeatWindowNanoseconds, 3'600'000 * kMillisecond}) {
    EXPECT_EQ(decide_stop(SIGHUP, kFirstAt + after, SIGHUP, kFirstAt, true), StopAction::ignore);
    EXPECT_EQ(decide_stop(SIGHUP, kFirstAt + after, SIGHUP, kFirstAt, false), StopAction::ignore);
  }
}

}  // namespace
}  // namespace raygate

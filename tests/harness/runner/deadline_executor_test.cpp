// Every child a measurement starts is bounded by the end of the user's budget (issue 25, class
// 10): the DeadlineExecutor lowers each run's timeout to the time left, never raises it, gives a
// run started past the deadline a second to fail in, and ends a real hanging child near it.
#include <gtest/gtest.h>

#include <chrono>

#include "fake_executor.h"
#include "runner/deadline_executor.h"

namespace raygate {
namespace {

using std::chrono::milliseconds;

// Records the timeouts it was asked to run with; each run takes `seconds` on the fake clock.
class TimeoutRecorder final : public Executor {
 public:
  TimeoutRecorder(testing::FakeClock& clock, double seconds) : clock_(clock), seconds_(seconds) {}
  ProcessResult run(const ProcessSpec& spec) override {
    timeouts.push_back(spec.timeout);
    clock_.advance(seconds_);
    return testing::exited_with(0, seconds_);
  }
  std::vector<ProcessResult> run_together(const std::vector<ProcessSpec>& specs) override {
    std::vector<ProcessResult> out;
    for (const ProcessSpec& spec : specs) timeouts.push_back(spec.timeout);
    clock_.advance(seconds_);
    out.assign(specs.size(), testing::exited_with(0, seconds_));
    return out;
  }
  std::vector<milliseconds> timeouts;

 private:
  testing::FakeClock& clock_;
  double seconds_;
};

ProcessSpec spec_with_timeout(milliseconds timeout) {
  ProcessSpec spec;
  spec.argv = {"tracer"};
  spec.timeout = timeout;
  return spec;
}

TEST(DeadlineExecutor, EachRunGetsAtMostTheTimeLeft) {
  testing::FakeClock clock;
  TimeoutRecorder inner(clock, 20.0);
  DeadlineExecutor bounded(inner, clock, clock.now_seconds() + 50.0);
  for (int i = 0; i < 4; ++i) bounded.run(spec_with_timeout(milliseconds(600'000)));
  // 50 s left, then 30, then 10, then past the deadline: the minimum second.
  EXPECT_EQ(inner.timeouts, (std::vector<milliseconds>{milliseconds(50'000), milliseconds(30'000),
                                                       milliseconds(10'000), milliseconds(1'000)}));
}

TEST(DeadlineExecutor, AShorterOwnTimeoutIsKeptAndNoTimeoutGetsOne) {
  testing::FakeClock clock;
  TimeoutRecorder inner(clock, 1.0);
  DeadlineExecutor bounded(inner, clock, clock.now_seconds() + 100.0);
  bounded.run(spec_with_timeout(milliseconds(5'000)));
  bounded.run(spec_with_timeout(milliseconds(0)));  // 0: none of its own
  bounded.run_together({spec_with_timeout(milliseconds(0)), spec_with_timeout(milliseconds(500))});
  EXPECT_EQ(inner.timeouts, (std::vector<milliseconds>{milliseconds(5'000), milliseconds(99'000),
                                                       milliseconds(98'000), milliseconds(500)}));
}

TEST(DeadlineExecutor, TheDeadlineLeavesAGraceForTheRoundUnderWay) {
  EXPECT_DOUBLE_EQ(measurement_deadline(100.0, 60.0), 100.0 + 60.0 + 15.0);
  EXPECT_DOUBLE_EQ(measurement_deadline(0.0, 4.0), 4.0 + 10.0);
}

// A real child that would sleep a minute is ended at the deadline, 1.5 s from now.
TEST(DeadlineExecutor, AHangingChildEndsNearTheDeadline) {
  SystemExecutor system;
  SteadyClock clock;
  DeadlineExecutor bounded(system, clock, clock.now_seconds() + 1.5);
  ProcessSpec spec;
  spec.argv = {"/bin/sleep", "60"};
  const ProcessResult result = bounded.run(spec);
  EXPECT_EQ(result.outcome, ProcessOutcome::timed_out) << result.describe();
  EXPECT_LT(result.wall_seconds, 5.0) << result.describe();
}

}  // namespace
}  // namespace raygate

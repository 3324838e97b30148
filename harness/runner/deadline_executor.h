// An Executor that bounds every child it starts by one deadline: the end of the budget the user
// gave the whole measurement (--max-minutes). The stopping rule only looks between rounds, and
// each contender's own run timeout is per run, so without it a tracer or baseline that hangs late
// in a measurement would still run its full timeout past the budget (issue 25, class 10).
#pragma once

#include "runner/executor.h"

namespace raygate {

class DeadlineExecutor final : public Executor {
 public:
  // `deadline_seconds` on `clock`'s scale. A run started at or after it still gets
  // kMinimumRunSeconds: it exists to fail with "timed out", not to be skipped silently.
  DeadlineExecutor(Executor& inner, Clock& clock, double deadline_seconds)
      : inner_(inner), clock_(clock), deadline_seconds_(deadline_seconds) {}

  ProcessResult run(const ProcessSpec& spec) override;
  std::vector<ProcessResult> run_together(const std::vector<ProcessSpec>& specs) override;

  static constexpr double kMinimumRunSeconds = 1.0;

 private:
  ProcessSpec bounded(ProcessSpec spec);

  Executor& inner_;
  Clock& clock_;
  double deadline_seconds_;
};

// The deadline of a measurement that started at `started_seconds` with a budget of
// `budget_seconds`: the budget and a grace for the round under way when it ran out (a quarter of
// the budget, at least 10 s), so a measurement that merely overran a little by finishing its
// round is not cut off as a timeout.
double measurement_deadline(double started_seconds, double budget_seconds);

}  // namespace raygate

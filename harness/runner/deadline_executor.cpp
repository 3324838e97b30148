#include "runner/deadline_executor.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace raygate {

ProcessSpec DeadlineExecutor::bounded(ProcessSpec spec) {
  const double left = std::max(deadline_seconds_ - clock_.now_seconds(), kMinimumRunSeconds);
  const auto left_ms = std::chrono::milliseconds(static_cast<long long>(std::ceil(left * 1000.0)));
  if (spec.timeout.count() == 0 || spec.timeout > left_ms) spec.timeout = left_ms;
  return spec;
}

ProcessResult DeadlineExecutor::run(const ProcessSpec& spec) { return inner_.run(bounded(spec)); }

std::vector<ProcessResult> DeadlineExecutor::run_together(const std::vector<ProcessSpec>& specs) {
  std::vector<ProcessSpec> out;
  out.reserve(specs.size());
  for (const ProcessSpec& spec : specs) out.push_back(bounded(spec));
  return inner_.run_together(out);
}

double measurement_deadline(double started_seconds, double budget_seconds) {
  return started_seconds + budget_seconds + std::max(10.0, 0.25 * budget_seconds);
}

}  // namespace raygate

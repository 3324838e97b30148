#include "builder/build_steps.h"

#include <fmt/format.h>

#include <algorithm>
#include <string_view>

#include "core/process.h"

namespace raygate {
namespace {

using Clock = std::chrono::steady_clock;

std::string step_label(std::size_t index, std::size_t count, const std::vector<std::string>& argv) {
  return fmt::format("step {} of {} `{}`", index + 1, count, argv_text(argv));
}

// A step that never started because the steps before it used up the build's time.
BuildStepRecord not_started(const std::vector<std::string>& argv, double timeout_seconds) {
  BuildStepRecord step;
  step.argv = argv;
  step.outcome = fmt::format("not started: the steps before it used up the build timeout of {} s",
                             timeout_seconds);
  return step;
}

BuildStepRecord run_one(const std::vector<std::string>& argv, const std::filesystem::path& log,
                        const StepSettings& settings, Clock::duration left) {
  ProcessSpec spec;
  spec.argv = argv;
  spec.working_directory = settings.working_directory;
  spec.stdout_path = log;
  spec.stderr_path = log;  // one log, in the order the tool wrote it
  // At least 1 ms: a zero timeout would mean none at all.
  spec.timeout =
      std::max(std::chrono::milliseconds(1), std::chrono::ceil<std::chrono::milliseconds>(left));
  const ProcessResult result = run_process(spec);

  BuildStepRecord step;
  step.argv = argv;
  step.outcome = result.describe();
  if (result.outcome == ProcessOutcome::timed_out) {
    step.outcome += fmt::format(" (timeout_s.build, {} s, covers all steps together)",
                                settings.timeout_seconds);
  }
  step.succeeded = result.succeeded();
  step.wall_seconds = result.wall_seconds;
  step.cpu_seconds = result.cpu_seconds();
  step.log = log;
  return step;
}

// Characters a shell takes literally; anything else gets the argument quoted in messages. Braces
// too, so that an adapter's templates show their placeholders as written ({src}, not '{src}').
bool shell_safe(const std::string& word) {
  return !word.empty() && std::all_of(word.begin(), word.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
           std::string_view("-_./=:,+@%{}").find(c) != std::string_view::npos;
  });
}

std::string quoted(const std::string& word) {
  if (shell_safe(word)) return word;
  std::string out = "'";
  for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

StepsResult run_build_steps(const std::vector<std::vector<std::string>>& steps,
                            const StepSettings& settings) {
  StepsResult result;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const Clock::duration left = settings.deadline - Clock::now();
    const std::string label = step_label(i, steps.size(), steps[i]);
    if (left <= Clock::duration::zero()) {
      result.steps.push_back(not_started(steps[i], settings.timeout_seconds));
      result.failure = label + " " + result.steps.back().outcome;
      return result;
    }
    const auto log = settings.logs_dir / fmt::format("step-{}.log", i + 1);
    result.steps.push_back(run_one(steps[i], log, settings, left));
    if (!result.steps.back().succeeded) {
      result.failure = label + " " + result.steps.back().outcome;
      result.log_tail = log_tail(log, kFailureLogLines);
      return result;
    }
  }
  result.success = true;
  return result;
}

std::string argv_text(const std::vector<std::string>& argv) {
  std::string text;
  for (const std::string& word : argv) {
    if (!text.empty()) text += ' ';
    text += quoted(word);
  }
  return text;
}

}  // namespace raygate

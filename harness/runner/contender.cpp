#include "runner/contender.h"

#include "core/error.h"

namespace raygate {

const std::filesystem::path& SceneInput::file(SceneFormat format) const {
  const auto found = files.find(format);
  if (found == files.end()) {
    throw InfraError("scene '" + entry.id + "' was not prepared in " +
                     std::string(to_string(format)) + " format");
  }
  return found->second;
}

RunRecord record_process(const ProcessResult& result, const ProcessSpec& spec) {
  RunRecord run;
  static_cast<ProcessUsage&>(run) = result;  // its times and peak, as the process reported them
  run.outcome = result.describe();
  run.log = spec.stdout_path;
  run.ok = result.succeeded();
  if (!run.ok) {
    run.failure = spec.argv.empty() ? run.outcome : spec.argv.front() + " " + run.outcome;
  }
  return run;
}

}  // namespace raygate

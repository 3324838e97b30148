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
  run.outcome = result.describe();
  run.wall_seconds = result.wall_seconds;
  run.user_seconds = result.user_seconds;
  run.system_seconds = result.system_seconds;
  run.max_rss_kib = result.max_rss_kib;
  run.max_rss_own = result.rss_own;
  run.peak_method = result.peak_method;
  run.log = spec.stdout_path;
  run.ok = result.succeeded();
  if (!run.ok) {
    run.failure = spec.argv.empty() ? run.outcome : spec.argv.front() + " " + run.outcome;
  }
  return run;
}

}  // namespace raygate

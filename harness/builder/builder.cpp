#include "builder/builder.h"

#include <sched.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <chrono>
#include <string_view>
#include <thread>

#include "adapter/packages.h"
#include "adapter/placeholders.h"
#include "builder/build_cache.h"
#include "builder/build_steps.h"
#include "builder/compiler_identity.h"
#include "checkout/file_lock.h"
#include "core/error.h"
#include "core/interrupt.h"
#include "core/sanitize.h"

namespace fs = std::filesystem;

namespace raygate {
namespace {

using Clock = std::chrono::steady_clock;

void require_packages(const Adapter& adapter) {
  std::vector<std::string> missing;
  try {
    missing = missing_packages(adapter);
  } catch (const InfraError&) {
    return;  // no dpkg: not a Debian system, the tools may be installed another way
  }
  if (missing.empty()) return;
  std::string names;
  for (const std::string& name : missing) names += (names.empty() ? "" : ", ") + name;
  throw InfraError(fmt::format(
      "{}: cannot build with adapter '{}': required Debian packages are not installed: {}\n"
      "  install them with: {}",
      adapter.file.string(), adapter.name, names, apt_get_line(missing)));
}

BuildKeyInputs key_inputs(const Worktree& worktree, const Adapter& adapter,
                          const BuildOptions& options) {
  BuildKeyInputs inputs;
  inputs.sha = worktree.sha;
  inputs.dirty = worktree.dirty;
  inputs.adapter_name = adapter.name;
  // What the build depends on, not the whole adapter: a new run line reuses the build.
  inputs.adapter_hash = build_inputs_hash(adapter, build_environment());
  inputs.compiler =
      options.compiler_identity ? *options.compiler_identity : detect_compiler_identity();
  inputs.extra = options.key_extra;
  return inputs;
}

BuildRecord new_record(const BuildKeyInputs& inputs, const BuildCacheEntry& entry,
                       const fs::path& src) {
  return {inputs, entry.key, entry.build_dir, src};
}

std::vector<std::vector<std::string>> expanded_steps(const Adapter& adapter,
                                                     const Worktree& worktree,
                                                     const BuildOptions& options,
                                                     const BuildRecord& record) {
  Placeholders values;
  values.src = record.src_dir.string();
  values.repo_root = worktree.path.string();
  values.build = record.build_dir.string();
  values.jobs = std::to_string(options.jobs > 0 ? options.jobs : available_cpus());
  values.raygate_source = options.raygate_source.string();
  std::vector<std::vector<std::string>> steps;
  for (const std::vector<std::string>& step : adapter.build) steps.push_back(expand(step, values));
  return steps;
}

// Log paths in the record follow the folder to its <key>.failed-N name.
void relocate_logs(BuildRecord& record, const fs::path& from, const fs::path& to) {
  if (from == to) return;
  for (BuildStepRecord& step : record.steps) {
    if (!step.log.empty()) step.log = to / step.log.lexically_relative(from);
  }
}

void run_steps(BuildRecord& record, const Worktree& worktree, const Adapter& adapter,
               const BuildOptions& options, const BuildCacheEntry& entry) {
  const auto started = Clock::now();
  if (!fs::is_directory(record.src_dir)) {
    record.failure =
        fmt::format("the source folder {} does not exist in this commit", record.src_dir.string());
    return;
  }
  StepSettings settings;
  settings.working_directory = record.src_dir;
  settings.logs_dir = entry.logs_dir;
  settings.timeout_seconds = adapter.timeouts.build_seconds;
  settings.deadline = started + std::chrono::duration_cast<Clock::duration>(
                                    std::chrono::duration<double>(settings.timeout_seconds));
  StepsResult result =
      run_build_steps(expanded_steps(adapter, worktree, options, record), settings);
  record.steps = std::move(result.steps);
  record.success = result.success;
  record.failure = std::move(result.failure);
  record.log_tail = std::move(result.log_tail);
  record.total_seconds = std::chrono::duration<double>(Clock::now() - started).count();
}

// Its steps' processes are gone (Process killed their groups); what they wrote is removed, so
// nothing of it can be taken for a build. The lock is still held.
void discard_interrupted_build(const BuildCacheEntry& entry) {
  std::error_code ignored;  // what stays is removed by the next build of the key anyway
  fs::remove_all(entry.dir, ignored);
}

}  // namespace

BuildRecord build(const Worktree& worktree, const Adapter& adapter, const BuildOptions& options) {
  const BuildKeyInputs inputs = key_inputs(worktree, adapter, options);
  const BuildCacheEntry entry = cache_entry(options.cache_dir, build_key(inputs));
  const fs::path src = source_directory(adapter, worktree.path);
  const FileLock lock(entry.lock);

  if (!inputs.dirty) {
    if (std::optional<BuildRecord> cached = read_cached_build(entry, inputs)) {
      cached->src_dir = src;  // the tree the caller will run in; same commit, same files
      return *cached;
    }
  }
  require_packages(adapter);
  prepare_fresh_entry(entry);
  BuildRecord record = new_record(inputs, entry, src);
  try {
    run_steps(record, worktree, adapter, options, entry);
    // A step that ended by itself while the signal arrived does not make the build complete.
    throw_if_interrupted("after the build steps");
  } catch (const Interrupted& stop) {
    discard_interrupted_build(entry);
    throw Interrupted(stop.signal(), fmt::format("interrupted by {} while building {}; the "
                                                 "unfinished build was removed (the next run "
                                                 "builds it again)",
                                                 signal_name(stop.signal()), entry.key));
  }
  if (record.success) {
    if (!inputs.dirty) publish_build(entry, record);
    return record;
  }
  const fs::path kept = set_aside_failed_build(entry);
  relocate_logs(record, entry.dir, kept);
  return record;
}

namespace {

bool contains_word(std::string_view line, std::string_view word) {
  const auto lower = [](char c) {
    return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  };
  std::string text(line);
  std::transform(text.begin(), text.end(), text.begin(), lower);
  return text.find(word) != std::string::npos;
}

// A configure step that downloads (CMake FetchContent, ExternalProject) fails offline; Debian
// ships many such sources as packages (googletest in /usr/src/googletest).
std::string download_hint(std::string_view line) {
  if (!contains_word(line, "could not resolve host") && !contains_word(line, "unable to access") &&
      !contains_word(line, "failed to connect")) {
    return "";
  }
  return "\n  the build downloads something and this machine is offline: point CMake at an "
         "installed copy with -DFETCHCONTENT_SOURCE_DIR_<NAME>=<dir> in the adapter's configure "
         "step (e.g. FETCHCONTENT_SOURCE_DIR_GOOGLETEST=/usr/src/googletest from the Debian "
         "package googletest; adapters/README.md)";
}

bool names_an_error(std::string_view line) {
  if (line.starts_with("-- ")) return false;  // CMake's "-- Looking for x - not found" chatter
  for (const std::string_view word :
       {"error:", "error ", "fatal:", "fatal error", "could not resolve", "undefined reference",
        "no such file or directory", "permission denied", "command not found",
        "unable to access"}) {
    if (contains_word(line, word)) return true;
  }
  return line.starts_with("CMake Error") || line.starts_with("Error");
}

}  // namespace

std::optional<LogLine> first_error_line(const fs::path& log) {
  std::ifstream in(log);
  if (!in) return std::nullopt;
  std::size_t number = 0;
  for (std::string line; std::getline(in, line);) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (names_an_error(line)) return LogLine{number, line.substr(0, 400)};
  }
  return std::nullopt;
}

std::vector<fs::path> built_executables(const fs::path& build_dir, std::size_t limit) {
  std::vector<fs::path> found;
  std::error_code ec;
  fs::recursive_directory_iterator it(build_dir, fs::directory_options::skip_permission_denied, ec);
  for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (it->is_directory(ec) &&
        (name == "CMakeFiles" || name == "_deps" || name.starts_with("."))) {
      it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file(ec)) continue;
    const auto perms = it->status(ec).permissions();
    if ((perms & fs::perms::owner_exec) == fs::perms::none) continue;
    if (name.ends_with(".so") || name.find(".so.") != std::string::npos || name.ends_with(".sh")) {
      continue;
    }
    found.push_back(it->path().lexically_relative(build_dir));
  }
  std::sort(found.begin(), found.end());
  if (found.size() > limit) found.resize(limit);
  return found;
}

std::string failure_message(const BuildRecord& record) {
  if (record.success) return "";
  std::string message =
      fmt::format("build failed: adapter '{}', commit {}{}: {}", record.adapter_name,
                  record.sha.substr(0, 12), record.dirty ? " (dirty)" : "", record.failure);
  message += fmt::format("\n  source: {}", record.src_dir.string());
  if (!record.steps.empty() && !record.steps.back().log.empty()) {
    const fs::path& log = record.steps.back().log;
    message += fmt::format("\n  log: {}", log.string());
    if (const std::optional<LogLine> first = first_error_line(log)) {
      // The log's bytes escaped: a NUL in it ended the error's what() there, dropping the rest.
      message += fmt::format("\n  first error (line {} of the log): {}", first->number,
                             terminal_line(first->text));
      message += download_hint(first->text);
    }
    if (record.log_tail.empty()) {
      message += "\n  (the log is empty)";
    } else {
      message += fmt::format("\n  last lines of the log:");
      std::string_view tail = record.log_tail;
      while (!tail.empty()) {
        const std::size_t end = std::min(tail.find('\n'), tail.size());
        message += fmt::format("\n    | {}", terminal_line(tail.substr(0, end)));
        tail.remove_prefix(std::min(end + 1, tail.size()));
      }
    }
  }
  message +=
      "\n  fix the build of this commit or the adapter's build steps (`raygate adapter check`); "
      "a commit that does not build is never measured";
  return message;
}

void require_success(const BuildRecord& record) {
  if (!record.success) throw InfraError(failure_message(record));
}

int available_cpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? static_cast<int>(n) : 1;
}

}  // namespace raygate

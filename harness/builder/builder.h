// The build stage (DESIGN.md §2): a worktree and an adapter in, a BuildRecord out. Runs the
// adapter's build steps once per (commit, adapter hash, compiler identity) into raygate's cache
// (build_cache.h) and hands back the cached record afterwards; a dirty worktree is rebuilt every
// time. A failed build is a result (bisect skips such commits); require_success() turns it into
// the exit-3 error the other commands need. docs/builder.md has the guarantees.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "adapter/adapter.h"
#include "builder/build_record.h"
#include "checkout/worktree.h"

namespace raygate {

struct BuildOptions {
  std::filesystem::path cache_dir;       // builds go in <cache_dir>/builds/
  std::filesystem::path raygate_source;  // {raygate_source}
  int jobs = 0;                          // {jobs}; 0: the CPUs this process may run on
  // nullopt: detect_compiler_identity(). Callers building many commits detect it once.
  std::optional<std::string> compiler_identity;
  // Anything else the build depends on, hashed into the key: e.g. raygate's own version when
  // the adapter builds {raygate_source}, whose files the commit sha does not cover.
  std::string key_extra;
};

// Builds `worktree` with `adapter`, or returns the cached successful build (cached = true, no
// step runs). Two processes building the same key wait for each other on a lock file; the
// second one then finds the first one's build.
//
// A step that exits non-zero, crashes, times out or cannot start fails the build: the record
// has success = false, names the step, holds the log tail, and the folder is set aside as
// <key>.failed-N, so nothing of it is ever used. Throws InfraError when a package in the
// adapter's "requires" is not installed (before any step runs; the message has the apt-get
// line) or when the cache itself cannot be written.
BuildRecord build(const Worktree& worktree, const Adapter& adapter, const BuildOptions& options);

// What went wrong, where, the first error line of the log (the cause, often far above the
// tail: "Could not resolve host" 80 lines before "Build step for googletest failed"), the last
// lines, and what to do; "" for a successful build.
std::string failure_message(const BuildRecord& record);

// The first line of a build log that names an error ("error:", "CMake Error", "fatal:",
// "Could not resolve host", "undefined reference"...), with its 1-based line number; nullopt
// when none does or the log cannot be read.
struct LogLine {
  std::size_t number = 0;
  std::string text;
};
std::optional<LogLine> first_error_line(const std::filesystem::path& log);

// Executable regular files under `build_dir` (CMake's own CMakeFiles/ and _deps/ trees
// skipped), relative to it, sorted, at most `limit`: what a wrong `run` path is told to pick from.
std::vector<std::filesystem::path> built_executables(const std::filesystem::path& build_dir,
                                                     std::size_t limit = 12);

// Throws InfraError(failure_message(record)) unless the build succeeded.
void require_success(const BuildRecord& record);

// The CPUs this process may run on (its affinity mask), at least 1.
int available_cpus();

}  // namespace raygate

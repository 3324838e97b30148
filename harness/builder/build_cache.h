// The build cache: one folder per (commit, build inputs, compiler identity), so a commit is
// built once per way of building it and toolchain, and a later run, compare or bisect step
// reuses it. The build inputs are what of the adapter the build depends on (its steps, source
// folder, packages, submodules) and the build tools' environment variables, not how the tracer
// is run: fixing an adapter's `run` line does not rebuild.
//
//   <cache>/builds/<key>.lock        flock'd while the entry is looked up or built
//   <cache>/builds/<key>/build/      {build}
//   <cache>/builds/<key>/logs/step-N.log
//   <cache>/builds/<key>/build.json  the BuildRecord, written atomically, last, only on success
//   <cache>/builds/<key>.failed-N/   a failed build, kept for its logs (the newest few)
//
// An entry is usable exactly when its build.json exists and says success; anything else in the
// folder is a dead or failed run's leftover and is removed before the key is built again.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "adapter/adapter.h"
#include "builder/build_record.h"

namespace raygate {

// The environment variables compilers and build systems read (CC, CXXFLAGS, CMAKE_GENERATOR,
// PKG_CONFIG_PATH...) that are set in this process: a build inherits them, so they are inputs.
std::map<std::string, std::string> build_environment();

// Hex SHA-256 of what of the adapter a build depends on, with `environment`: the build steps as
// written (before {jobs} and paths are filled in), source_dir, requires and submodules. Not the
// run command, image, timing, timeouts or description: those change no file the build makes.
std::string build_inputs_hash(const Adapter& adapter,
                              const std::map<std::string, std::string>& environment);

// Hex SHA-256 (16 digits) of what a measurement depends on besides the commit: the build's
// inputs (`build_hash`) and how the tracer is run (run, stdin, cwd, env, threads, pinning,
// timing, scene format). A history series keys on it (results/series.h), so builds with other
// flags or runs with other options are never one trend.
std::string measurement_hash(const Adapter& adapter, const std::string& build_hash);

// What a build depends on, besides the files of the commit: what its record keeps, and more.
struct BuildKeyInputs : BuildIdentity {
  std::string extra;  // anything else the caller knows the build depends on
};

// "<adapter name>-<12 sha digits>[-dirty]-<16 hex digits of SHA-256 over all inputs>": readable
// in a directory listing, and changing any input changes it.
std::string build_key(const BuildKeyInputs& inputs);

struct BuildCacheEntry {
  std::string key;
  std::filesystem::path dir;        // <cache>/builds/<key>
  std::filesystem::path build_dir;  // dir/build
  std::filesystem::path logs_dir;   // dir/logs
  std::filesystem::path record;     // dir/build.json
  std::filesystem::path lock;       // <cache>/builds/<key>.lock
};

BuildCacheEntry cache_entry(const std::filesystem::path& cache_dir, const std::string& key);

// The entry's record if it is a successful build of exactly these inputs (cached = true);
// nothing if it is absent, failed, unreadable, or for other inputs. Call with the lock held.
std::optional<BuildRecord> read_cached_build(const BuildCacheEntry& entry,
                                             const BuildKeyInputs& inputs);

// Removes whatever is left in the entry and creates empty build/ and logs/ folders, so no file
// of an earlier attempt can be taken for this build's output. Call with the lock held.
void prepare_fresh_entry(const BuildCacheEntry& entry);

// Publishes a successful build: build.json, after the build's files are on disk.
void publish_build(const BuildCacheEntry& entry, const BuildRecord& record);

// Moves a failed build's folder to <key>.failed-N (N one more than the newest) and deletes all
// but the newest few of those. Returns the new folder, or entry.dir if it could not be moved.
std::filesystem::path set_aside_failed_build(const BuildCacheEntry& entry);

}  // namespace raygate

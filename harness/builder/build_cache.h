// The build cache: one folder per (commit, adapter hash, compiler identity), so a commit is
// built once per adapter and toolchain, and a later run, compare or bisect step reuses it.
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
#include <optional>
#include <string>

#include "builder/build_record.h"

namespace raygate {

// What a build depends on, besides the files of the commit.
struct BuildKeyInputs {
  std::string sha;
  bool dirty = false;  // gets its own key, so a dirty build never replaces a clean one
  std::string adapter_name;
  std::string adapter_hash;
  std::string compiler;  // detect_compiler_identity()
  std::string extra;     // anything else the caller knows the build depends on
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

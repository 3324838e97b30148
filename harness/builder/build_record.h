// The record of one build (DESIGN.md §2: worktree --builder--> BuildRecord): which commit, adapter
// and compiler it was for, where it lives, what each step ran and how that ended. The runner reads
// build_dir from it, results documents store it, and the cache keeps it as build.json, which is
// why it converts to and from JSON.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace raygate {

// One build step as it ran.
struct BuildStepRecord {
  std::vector<std::string> argv;  // after placeholder expansion
  std::string outcome;            // ProcessResult::describe(): "exited with status 0", ...
  bool succeeded = false;
  double wall_seconds = 0.0;
  double cpu_seconds = 0.0;   // user + system, children included
  std::filesystem::path log;  // stdout and stderr together

  bool operator==(const BuildStepRecord&) const = default;
};

// What a build is of: the commit, the adapter and the compiler. The cache key is made of these
// (with BuildKeyInputs::extra, build_cache.h) and the record keeps them.
struct BuildIdentity {
  std::string sha;     // the worktree's commit ("uncommitted" outside git)
  bool dirty = false;  // local changes: never cached, and a key of its own
  std::string adapter_name;
  std::string adapter_hash;  // build_inputs_hash(), not the whole adapter
  std::string compiler;      // compiler identity text (compiler_identity.h)

  bool operator==(const BuildIdentity&) const = default;
};

struct BuildRecord : BuildIdentity {
  std::string key;                       // cache key: names <cache>/builds/<key>/
  std::filesystem::path build_dir;       // {build}
  std::filesystem::path src_dir;         // {src} of the worktree this record was handed out for
  std::vector<BuildStepRecord> steps{};  // those that ran; on failure the last one failed
  double total_seconds = 0.0;
  bool cached = false;  // reused from an earlier successful build; no step ran now
  bool success = false;
  std::string failure{};   // on failure: what went wrong, one line
  std::string log_tail{};  // on failure: the last lines of the failed step's log

  bool operator==(const BuildRecord&) const = default;
};

// The build.json form. Reading throws nlohmann::json::exception for a document that is not a
// build record (the cache then treats the entry as absent).
nlohmann::json build_record_to_json(const BuildRecord& record);
BuildRecord build_record_from_json(const nlohmann::json& document);

}  // namespace raygate

// The results document (DESIGN.md §8): everything one `raygate run` or `raygate compare`
// measured, self-describing and versioned, so a document read back months later (history,
// report, merge of CI shards) means exactly what it meant when written. Written atomically after
// every scene, so a run that is killed keeps the scenes it finished (`complete` stays false).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "builder/build_record.h"
#include "checkout/worktree.h"
#include "compare/image_check.h"
#include "core/domain.h"
#include "explain/explanation.h"
#include "measure/change.h"
#include "measure/ratio.h"
#include "results/measurement_settings.h"
#include "results/scaling_record.h"
#include "runner/scheduler.h"
#include "runner/suite.h"

namespace raygate {

inline constexpr int kResultsSchemaVersion = 1;

// One measured revision of the tracer and how it was built.
struct RevisionRecord {
  Role role = Role::tracer;   // tracer for run; base and head for compare
  std::string repository;     // as the user named it: a path or a URL
  std::string repository_id;  // checkout/repository_identity.h; "" when not known
  Worktree worktree;
  std::string adapter_name;
  std::string adapter_hash;
  std::string adapter_file;
  // builder/build_cache.h measurement_hash: what the measurement depends on (build inputs and
  // how the tracer is run); a history series keys on it. "" in documents from before issue 26.
  std::string adapter_measurement;
  BuildRecord build;
};

struct BaselineRecord {
  std::string version;  // raygate-baseline --version
  std::string source_sha256;
  std::string accel = "none";
  std::string sampling = "center";
  // The clock the ratios divide by, matched to the tracer's (runner/baseline_contender.h):
  // "process-wall", "process-cpu", or "in-process" (parse + prepare + render seconds from
  // --stats, against a tracer that reports its own time). Documents written before the clocks
  // were matched say "in-process", or "in-process-cpu" (in-process CPU seconds).
  std::string timing = "process-wall";
};

struct SceneResult {
  SuiteScene entry;
  std::string scene_sha256;  // of the NFF file measured
  SceneStatus status = SceneStatus::measured;
  SceneRuns runs;
  std::map<Role, RatioSummary> ratios;  // by revision role, each against the baseline
  std::optional<ChangeSummary> change;  // compare: head against base
  // compare: the change's verdict under the policy it was measured with (with `change` only).
  ChangeVerdict change_verdict = ChangeVerdict::inconclusive;
  std::vector<ImageCheck> images;
  // compare: where a REGRESSED scene's time went, by function (explain/explanation.h).
  std::optional<Explanation> explanation;

  const RatioSummary* ratio(Role role) const;
};

struct ResultsDocument {
  int schema_version = kResultsSchemaVersion;
  DocumentKind kind = DocumentKind::run;
  std::string raygate_version;
  std::string started_at;   // ISO-8601 UTC
  std::string finished_at;  // empty while running
  bool complete = false;    // every selected scene has a result
  nlohmann::json machine;   // MachineContext as JSON (machine_context.h)
  BaselineRecord baseline;
  std::string suite;
  std::string shard;  // "K/N" when the suite was split across jobs (split: settings.shard)
  MeasurementSettings settings;  // schedule, stopping policy, clocks, limits, pinning, shard
  std::vector<RevisionRecord> revisions;
  std::vector<SceneResult> scenes;
  std::map<Role, SuiteScore> scores;  // by role: geometric mean over measured scenes
  // Growth exponents per scene family (results/scaling_record.h; fitted by scaling/), when the
  // suite measured a family at 3 sizes or more; absent (null in JSON) otherwise.
  std::optional<ScalingAnalysis> scaling;

  const RevisionRecord* revision(Role role) const;
};

nlohmann::json to_json(const ResultsDocument& document);
// Throws UsageError naming `origin` and the JSON path for a document raygate cannot read,
// including one with a newer schema_version than this raygate knows.
ResultsDocument results_from_json(const nlohmann::json& json, const std::string& origin);

// Atomic (core/fs.h): a reader never sees half a document.
void write_results(const ResultsDocument& document, const std::filesystem::path& path);
ResultsDocument read_results(const std::filesystem::path& path);

}  // namespace raygate

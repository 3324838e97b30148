// A contender is one program the scheduler times on a scene: the baseline (the normalizer) or a
// tracer revision built through an adapter. It knows how to start one run in a fresh directory
// and how to turn the finished process into a RunRecord; the scheduler decides when and in which
// order runs happen.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "adapter/adapter.h"
#include "builder/build_record.h"
#include "core/domain.h"
#include "core/fs.h"
#include "core/process.h"
#include "runner/run_record.h"
#include "runner/suite.h"

namespace raygate {

// A suite scene ready to render: its NFF file and, for adapters that read other formats, the
// converted files.
struct SceneInput {
  SuiteScene entry;
  std::filesystem::path nff;
  std::map<SceneFormat, std::filesystem::path> files;  // always holds nff too
  // Each file's stamp as prepared, checked after every run (runner/scheduler.cpp): every
  // contender reads the same file, so a run that writes it changes what the next is timed on.
  // Empty: not checked (tests' scenes that are only names).
  std::map<std::filesystem::path, FileStamp> prepared_stamps;

  // The file in `format`; throws InfraError if it was not prepared.
  const std::filesystem::path& file(SceneFormat format) const;
};

class Contender {
 public:
  explicit Contender(Role role) : role_(role) {}
  virtual ~Contender() = default;

  Role role() const { return role_; }
  // The role's word ("baseline", "tracer", "base", "head"): the contender's key in rounds and
  // documents, and its run directory.
  std::string name() const { return role_name(role_); }

  // The process of one run whose files go in `run_dir` (created by the caller, empty).
  virtual ProcessSpec command(const SceneInput& scene,
                              const std::filesystem::path& run_dir) const = 0;

  // A run whose result is already known, so the scheduler need not start it (the baseline's
  // cached simulated cost); nullopt, the default: run it.
  virtual std::optional<RunRecord> known_run(const SceneInput& /*scene*/) const {
    return std::nullopt;
  }

  // The record of that run once its process ended.
  virtual RunRecord interpret(const SceneInput& scene, const ProcessResult& result,
                              const ProcessSpec& spec,
                              const std::filesystem::path& run_dir) const = 0;

 private:
  Role role_;
};

// The common part of interpret(): outcome, times, log; ok only if the process succeeded.
RunRecord record_process(const ProcessResult& result, const ProcessSpec& spec);

}  // namespace raygate

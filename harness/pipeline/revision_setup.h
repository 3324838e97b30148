// From a revision name to a tracer contender: check the commit out into the worktree cache (or
// take the user's --worktree as it is), build it through the adapter (cached), and describe it
// for the results document. Shared by run, compare and bisect.
#pragma once

#include <string>

#include "checkout/repository.h"
#include "pipeline/measure_context.h"
#include "pipeline/pipeline_io.h"
#include "results/results.h"
#include "runner/tracer_contender.h"

namespace raygate {

// What a measuring command names and where it is: the worktrees and the repository as the
// document records it (its location as opened).
struct RunTree {
  Worktree worktree;
  std::string repository;
};
struct CompareTrees {
  Worktree base;
  Worktree head;
  std::string repository;
};

// The tree `raygate run` measures: `rev` of `repo` checked out into the worktree cache, or, when
// `worktree` is not empty, that directory as it is (uncommitted changes included, recorded as
// dirty).
RunTree locate_run_tree(const std::string& repo, const std::string& rev,
                        const std::string& worktree, const std::filesystem::path& cache_dir);

// compare's two sides: `head`, and `base` or, when `base` is empty, the merge base of head and
// `base_branch` (what a pull request changes); UsageError when they have none.
CompareTrees locate_compare_trees(const std::string& repo, const std::string& base,
                                  const std::string& base_branch, const std::string& head,
                                  const std::filesystem::path& cache_dir);

struct PreparedRevision {
  RevisionRecord record;
  TracerSetup setup;
};

// Builds `worktree` for `role`; throws InfraError (exit 3) with the log tail if the build fails.
PreparedRevision prepare_revision(Role role, const std::string& repository,
                                  const Worktree& worktree, const MeasureContext& context,
                                  const std::string& baseline_source_hash, int jobs,
                                  ProgressSink& progress);

// The contender for `worktree` built as `build_record` (a successful build).
PreparedRevision prepared_revision(Role role, const std::string& repository,
                                   const Worktree& worktree, const MeasureContext& context,
                                   const BuildRecord& build_record);

// Throws InfraError (exit 3) unless the adapter's run program is where the build should have
// put it: said once, with the executables the build did make, before any scene is measured.
// Programs found on PATH, or named by placeholders only a run knows ({workdir}), are not checked.
void require_run_program(const Adapter& adapter, const BuildRecord& build,
                         const std::filesystem::path& repo_root,
                         const std::filesystem::path& raygate_source);

// A compare's two builds: nothing when both succeeded, else InfraError saying how each side
// did (issue 26: compare stopped at base's failure and never said whether head builds).
void require_both_built(const BuildRecord& base, const BuildRecord& head);

// The build record for `worktree` without throwing on failure (bisect skips such commits).
BuildRecord build_revision(const Worktree& worktree, const MeasureContext& context,
                           const std::string& baseline_source_hash, int jobs,
                           ProgressSink& progress);

}  // namespace raygate

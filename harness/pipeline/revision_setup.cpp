#include "pipeline/revision_setup.h"

#include <fmt/core.h>

#include "adapter/placeholders.h"
#include "builder/build_cache.h"
#include "builder/builder.h"
#include "checkout/repository_identity.h"
#include "core/error.h"
#include "measure/stopping_policy.h"

namespace raygate {

RunTree locate_run_tree(const std::string& repo, const std::string& rev,
                        const std::string& worktree, const std::filesystem::path& cache_dir) {
  if (!worktree.empty()) {
    const std::filesystem::path path = std::filesystem::absolute(worktree);
    // The user's arguments, refused before anything is built (a folder that is not there was
    // reported as a failed build, exit 3; a --rev beside it was silently not measured).
    std::error_code error;
    if (!std::filesystem::is_directory(path, error)) {
      throw UsageError("--worktree " + path.string() + ": no such folder");
    }
    if (rev != "HEAD") {
      throw UsageError("--rev " + rev.substr(0, 60) + " and --worktree " + path.string() +
                       " both given: a worktree is measured as it is; give one of them");
    }
    Worktree tree = describe_uncommitted_worktree(path);
    tree.revision = "--worktree " + path.string();
    return {tree, path.string()};
  }
  const Repository repository = Repository::open(repo, cache_dir);
  return {repository.checkout(rev), repository.location()};
}

CompareTrees locate_compare_trees(const std::string& repo, const std::string& base,
                                  const std::string& base_branch, const std::string& head,
                                  const std::filesystem::path& cache_dir) {
  const Repository repository = Repository::open(repo, cache_dir);
  CompareTrees trees;
  trees.repository = repository.location();
  trees.head = repository.checkout(head);
  if (!base.empty()) {
    trees.base = repository.checkout(base);
    return trees;
  }
  const std::optional<Revision> merge_base = repository.merge_base(head, base_branch);
  if (!merge_base) {
    throw UsageError(
        fmt::format("{} and {} have no common ancestor; pass --base REV", head, base_branch));
  }
  Revision named = *merge_base;
  named.revision = "merge-base(" + head + ", " + base_branch + ")";
  trees.base = repository.materialize(named);
  return trees;
}

namespace {

bool builds_raygate_source(const Adapter& adapter) {
  for (const auto& step : adapter.build) {
    for (const std::string& arg : step) {
      if (uses_placeholder(arg, "raygate_source")) return true;
    }
  }
  return false;
}

}  // namespace

BuildRecord build_revision(const Worktree& worktree, const MeasureContext& context,
                           const std::string& baseline_source_hash, int jobs,
                           ProgressSink& progress) {
  BuildOptions options;
  options.cache_dir = context.cache_dir;
  options.raygate_source = context.tools.data_root;
  options.jobs = jobs;
  // The commit does not cover files the adapter builds from raygate's own tree.
  if (builds_raygate_source(context.adapter)) {
    options.key_extra = "raygate-baseline-source:" + baseline_source_hash;
  }
  progress.status(fmt::format("building {} ({}) with adapter {} ...", worktree.short_sha,
                              worktree.revision, context.adapter.name));
  BuildRecord record = build(worktree, context.adapter, options);
  if (record.success) {
    progress.status(fmt::format("  {} in {}", record.cached ? "cached build" : "built",
                                record.build_dir.string()));
  }
  return record;
}

PreparedRevision prepare_revision(Role role, const std::string& repository,
                                  const Worktree& worktree, const MeasureContext& context,
                                  const std::string& baseline_source_hash, int jobs,
                                  ProgressSink& progress) {
  const BuildRecord build_record =
      build_revision(worktree, context, baseline_source_hash, jobs, progress);
  require_success(build_record);
  require_run_program(context.adapter, build_record, worktree.path, context.tools.data_root);
  return prepared_revision(role, repository, worktree, context, build_record);
}

namespace {

// CMake configured this build folder: it left its cache there.
bool configured_by_cmake(const std::filesystem::path& build_dir) {
  std::error_code ec;
  return std::filesystem::is_regular_file(build_dir / "CMakeCache.txt", ec);
}

}  // namespace

void require_run_program(const Adapter& adapter, const BuildRecord& build,
                         const std::filesystem::path& repo_root,
                         const std::filesystem::path& raygate_source) {
  if (adapter.run.empty()) return;
  const std::string& written = adapter.run.front();
  for (const char* name :
       {"workdir", "scene", "image", "scene_stem", "threads", "width", "height", "jobs", "seed"}) {
    if (uses_placeholder(written, name)) return;  // known only at run time
  }
  Placeholders values;
  values.src = build.src_dir.string();
  values.repo_root = repo_root.string();
  values.build = build.build_dir.string();
  values.raygate_source = raygate_source.string();
  const std::filesystem::path program = expand(written, values);
  // A bare name is looked up on PATH, a relative path from the run's working folder.
  if (!program.is_absolute() || std::filesystem::exists(program)) return;
  std::string message =
      fmt::format("adapter '{}': its run program {} does not exist after the build (`run` in {})",
                  adapter.name, written, adapter.file.string());
  const std::vector<std::filesystem::path> made = built_executables(build.build_dir);
  if (made.empty()) {
    message += fmt::format("\n  the build made no executable under {{build}} ({})",
                           build.build_dir.string());
  } else {
    message += "\n  the build made these executables:";
    for (const std::filesystem::path& path : made) message += "\n    {build}/" + path.string();
  }
  // Where CMake puts a subproject's target is the usual surprise; a Makefile or other build
  // puts its programs where its own rules say, so the hint would mislead there.
  message += configured_by_cmake(build.build_dir)
                 ? "\n  a CMake add_subdirectory(x) target lands in {build}/x/; fixing `run` "
                   "reuses this build (adapters/README.md)"
                 : "\n  fixing `run` reuses this build (adapters/README.md)";
  throw InfraError(message);
}

void require_both_built(const BuildRecord& base, const BuildRecord& head) {
  if (base.success && head.success) return;
  const auto side = [](Role role, const BuildRecord& r) {
    return r.success ? fmt::format("{} ({}) built", to_string(role), r.sha.substr(0, 12))
                     : fmt::format("{} did not build:\n{}", to_string(role), failure_message(r));
  };
  throw InfraError(fmt::format("{}\n{}", side(Role::base, base), side(Role::head, head)));
}

PreparedRevision prepared_revision(Role role, const std::string& repository,
                                   const Worktree& worktree, const MeasureContext& context,
                                   const BuildRecord& build_record) {
  PreparedRevision prepared;
  prepared.record.role = role;
  prepared.record.repository = repository;
  prepared.record.repository_id = repository_identity(repository, worktree.sha, context.cache_dir);
  prepared.record.worktree = worktree;
  prepared.record.adapter_name = context.adapter.name;
  prepared.record.adapter_hash = adapter_hash(context.adapter);
  prepared.record.adapter_file = context.adapter.file.string();
  prepared.record.adapter_measurement =
      measurement_hash(context.adapter, build_record.adapter_hash);
  prepared.record.build = build_record;
  prepared.setup.role = role;
  prepared.setup.adapter = context.adapter;
  prepared.setup.build = build_record;
  prepared.setup.repo_root = worktree.path;
  prepared.setup.raygate_source = context.tools.data_root;
  prepared.setup.timing = &timing_mode(context);
  prepared.setup.cachegrind = context.cachegrind;
  // The adapter's own limit, and the user's budget too (issue 25, class 10), as the baseline's.
  prepared.setup.run_timeout_seconds =
      budgeted_run_seconds(context.stopping, context.adapter.timeouts.run_seconds);
  // The adapter asks raygate to pin: the first `threads` CPUs this process may use.
  prepared.setup.cpus = adapter_pinned_cpus(context);
  return prepared;
}

}  // namespace raygate

#include "pipeline/revision_setup.h"

#include <fmt/core.h>

#include "adapter/placeholders.h"
#include "builder/builder.h"
#include "checkout/repository_identity.h"
#include "measure/stopping.h"

namespace raygate {

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

PreparedRevision prepare_revision(const std::string& role, const std::string& repository,
                                  const Worktree& worktree, const MeasureContext& context,
                                  const std::string& baseline_source_hash, int jobs,
                                  ProgressSink& progress) {
  const BuildRecord build_record =
      build_revision(worktree, context, baseline_source_hash, jobs, progress);
  require_success(build_record);
  return prepared_revision(role, repository, worktree, context, build_record);
}

PreparedRevision prepared_revision(const std::string& role, const std::string& repository,
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
  prepared.record.build = build_record;
  prepared.setup.role = role;
  prepared.setup.adapter = context.adapter;
  prepared.setup.build = build_record;
  prepared.setup.repo_root = worktree.path;
  prepared.setup.raygate_source = context.tools.data_root;
  prepared.setup.metric = context.metric;
  prepared.setup.cachegrind = context.cachegrind;
  // The adapter's own limit, and the user's budget too (issue 25, class 10), as the baseline's.
  prepared.setup.run_timeout_seconds =
      budgeted_run_seconds(context.stopping, context.adapter.timeouts.run_seconds);
  if (context.adapter.pin_cpus && context.schedule.pin_cpus.empty()) {
    // The adapter asks raygate to pin: the first `threads` CPUs this process may use.
    const std::vector<int> allowed = allowed_cpu_list();
    const std::size_t count =
        std::min(allowed.size(), static_cast<std::size_t>(std::max(context.adapter.threads, 1)));
    prepared.setup.cpus.assign(allowed.begin(), allowed.begin() + static_cast<long>(count));
  }
  return prepared;
}

}  // namespace raygate

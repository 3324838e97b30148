// Measuring one revision of a tracer against the baseline on a suite (`raygate run`): build it,
// then rounds of (baseline, tracer) per scene until the ratio is known to the target precision
// or the scene's budget is spent; ratios, image checks, and the suite score.
#pragma once

#include <filesystem>
#include <string>

#include "checkout/worktree.h"
#include "pipeline/measure_context.h"
#include "pipeline/pipeline_io.h"
#include "pipeline/revision_setup.h"
#include "pipeline/suite_measurement.h"
#include "runner/baseline_tool.h"

namespace raygate {

struct RunRequest {
  const MeasureContext& context;
  const BaselineTool& baseline;
  std::string repository;     // as the user named it, for the document
  Worktree worktree;          // a checked-out commit, or the user's own tree
  std::filesystem::path out;  // results document; "" = in the run's work directory
};

// Builds the revision (InfraError with the log tail if the build fails), measures, and returns
// the complete document, also written to its path.
MeasuredDocument measure_run(const RunRequest& request, PipelineIo& io);

// The measuring half of measure_run, on a revision already built.
MeasuredDocument measure_prepared_run(const RunRequest& request, const PreparedRevision& tracer,
                                      PipelineIo& io);

}  // namespace raygate

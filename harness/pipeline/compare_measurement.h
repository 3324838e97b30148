// Measuring two revisions against each other (shared by compare and bisect): both built, then
// rounds of (baseline, base, head) in rotating order until each scene's verdict is decided or
// its budget is spent; per scene the change with its CI, the verdict, and head's image against
// base's.
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

struct CompareRequest {
  const MeasureContext& context;
  const BaselineTool& baseline;
  std::string repository;  // for the document
  Worktree base;
  Worktree head;
  std::filesystem::path out;  // results document; "" = in the run's work directory
  // Ratio rounds for stored ratios still imprecise (pipeline/stored_ratio.h); bisect's steps
  // store no ratio and spend no time on them.
  bool ratio_rounds = true;
};

// Builds both (InfraError with the log tail if either build fails), measures, and returns the
// complete document, also written to its path.
MeasuredDocument measure_compare(const CompareRequest& request, PipelineIo& io);

// The measuring half of measure_compare, on revisions already built.
MeasuredDocument measure_prepared_compare(const CompareRequest& request,
                                          const PreparedRevision& base,
                                          const PreparedRevision& head, PipelineIo& io);

}  // namespace raygate

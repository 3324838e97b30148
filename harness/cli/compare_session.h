// Measuring two revisions against each other (shared by compare and bisect): both built, then
// rounds of (baseline, base, head) in rotating order until each scene's verdict is decided or
// its budget is spent; per scene the change with its CI, the verdict, and head's image against
// base's.
#pragma once

#include <filesystem>
#include <string>

#include "checkout/worktree.h"
#include "cli/measure_options.h"
#include "runner/baseline_tool.h"
#include "store/results.h"

namespace raygate::cli {

struct CompareSetup {
  const MeasureContext& context;
  const BaselineTool& baseline;
  std::string repository;  // for the document
  Worktree base;
  Worktree head;
  std::filesystem::path out;  // results document; "" = in the run's work directory
};

// Builds both (InfraError with the log tail if either build fails), measures, and returns the
// complete document, also written to its path (document_path says where).
ResultsDocument measure_compare(const CompareSetup& setup, std::filesystem::path* document_path);

// Stops a scene once its verdict is decided (REGRESSED, IMPROVED or UNCHANGED); an
// INCONCLUSIVE scene gets rounds until the budget is spent.
// `counted`: sim mode, where rounds whose counts all repeat decide exactly (measure/simulated_cost.h).
StopRule change_stop_rule(const StoppingPolicy& stopping, const ScenePolicy& policy,
                          bool counted = false);

}  // namespace raygate::cli

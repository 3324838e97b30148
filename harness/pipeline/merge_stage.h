// `raygate merge` as a library call: the documents of the shards of one CI matrix (run or
// compare with --shard K/N) joined into the document one job measuring every scene would have
// written (results/merge.h), written atomically to `out`, with the gate policy that judges it.
// Publishing it (store, gate, reports) is pipeline/publish.h's, as for run and compare.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "gate/policy.h"
#include "pipeline/output_failures.h"
#include "pipeline/publish.h"
#include "results/results.h"

namespace raygate {

struct MergeRequest {
  std::vector<std::string> documents;  // the shards' results documents
  std::string out;                     // the merged document (required)
  std::string policy;                  // a gate policy file; "" = the limits the shards recorded
  bool fail_on_inconclusive = false;
  bool allow_partial = false;  // merge even if whole shards are missing (incomplete: exit 3)
};

struct MergedShards {
  ResultsDocument document;
  GatePolicy policy;
};

// Reads, checks (UsageError for shards that do not belong together) and merges; a merged
// document that cannot be written to `out` is a failure in `failures`, not an error, so the store
// and the reports still get it. Says the policy's origin, the merge's warnings, what was merged
// and the suite scores through `sink`.
MergedShards merge_shard_documents(const MergeRequest& request, const PublishSink& sink,
                                   OutputFailures& failures);

}  // namespace raygate

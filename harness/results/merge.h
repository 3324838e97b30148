// `raygate merge`: the documents of the shards of one CI matrix (`--shard K/N`) combined into the
// document one job measuring every scene would have written: scenes in suite order, the suite
// score recomputed from the raw rounds. Shards that did not measure the same thing (another
// revision, adapter, baseline, suite, schema or settings; another shard count; the same scene
// twice) are refused with a UsageError naming both files and the field, because a merged verdict
// over them would mean nothing. docs/shards.md.
#pragma once

#include <string>
#include <vector>

#include "results/results.h"

namespace raygate {

struct MergeInput {
  std::string origin;  // where the document came from (its path), for messages
  ResultsDocument document;
};

struct MergeOptions {
  // Merge even when whole shards are missing (the result is incomplete, so the gate exits 3);
  // without it a missing shard is a UsageError.
  bool allow_partial = false;
};

struct MergeResult {
  ResultsDocument document;
  std::vector<std::string> warnings;  // missing shards or scenes, differing raygate versions
};

// Throws UsageError for no inputs, a document without a shard record, inconsistent shards,
// overlapping scenes, and (unless allow_partial) a missing shard.
MergeResult merge_shards(const std::vector<MergeInput>& inputs, const MergeOptions& options);

}  // namespace raygate

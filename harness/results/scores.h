// The suite score of a results document (geometric mean of the normalized ratios over its
// measured scenes, with the bootstrap interval; measure/ratio.h), recomputed from the raw rounds
// the document holds. One function for run, compare and merge, so the score of shards merged
// into one document is the score one job measuring every scene would have written.
#pragma once

#include <map>
#include <vector>

#include "results/results.h"

namespace raygate {

// By role (each of `roles` with at least one measured scene); scenes in the order given.
std::map<Role, SuiteScore> suite_scores(const std::vector<SceneResult>& scenes,
                                        const std::vector<Role>& roles);

// The roles a document's scores are over: its revisions' roles (tracer; base and head).
std::vector<Role> scored_roles(const ResultsDocument& document);

}  // namespace raygate

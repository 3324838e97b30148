// A bisection's answer as `raygate bisect` gives it: the exit code (0 found, 2 the bad end is not
// worse, 3 it could not be measured), the text (the first bad commit, a merge note, where its
// time went) and the JSON object with every step.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "core/exit_codes.h"
#include "pipeline/bisect.h"

namespace raygate {

// What the answer names besides the result: the scene followed, the metric word (ratio,
// image) and the bad end as the user named it.
struct BisectAnswerContext {
  std::string scene;
  std::string metric;
  std::string bad;
};

ExitCode bisect_exit_code(const BisectResult& result);

// {scene, metric, good, bad, candidates, steps: [...], result: {kind, ...}, exit_code}.
nlohmann::json bisect_json(const BisectResult& result, const BisectAnswerContext& context);

// The answer's lines, each ending in a newline (commit subjects not yet made terminal-safe).
std::string bisect_text(const BisectResult& result);

}  // namespace raygate

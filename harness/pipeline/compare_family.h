// The scenes of one compare judged as a family (measure/family.h): each scene's share of the
// family's significance while it is measured, Holm's step-down over the measured scenes once
// all are done, and the closing line that names the scenes still undecided and how wide their
// intervals are.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "gate/policy.h"
#include "results/results.h"
#include "runner/scheduler.h"

namespace raygate {

// The decision alpha (each side) of every scene while the compare measures: the family's
// significance split evenly over `family_size` scenes (the whole selection, even in a shard).
double scene_decision_alpha(const GatePolicy& policy, std::size_t family_size);

// ln(t_head / t_base) of each round, in order.
std::vector<double> log_changes(const std::vector<Round>& rounds);

// Holm over the document's measured scenes (a family of `family_size`): a scene REGRESSED at a
// looser share gets that share's summary and verdict. Exact scenes (sim mode) need no share and
// are left alone; so is a shard, which sees only some of the family's p-values and keeps the
// shares it was measured at. Returns the ids of the scenes it changed.
std::vector<std::string> apply_family_control(ResultsDocument& document, const GatePolicy& policy,
                                              std::size_t family_size);

// "undecided (INCONCLUSIVE): balls +1.2% [-3.1%, +6.0%] (width 9.1 points) after 40 rounds
// (about 90 rounds in all would decide it, 1 min more at this scene's pace, or a quieter
// runner); ..." for the INCONCLUSIVE scenes, or "" when every measured scene is decided.
std::string undecided_line(const ResultsDocument& document, const GatePolicy& policy);

}  // namespace raygate

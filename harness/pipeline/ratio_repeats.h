// How `raygate run` chooses, round by round, between one run of each program and each one's
// fastest of two (docs/statistics.md §6d), where --repeats is not given. `run` has no second
// pass: a scene's rounds go on until its ratio is known to ±1% or its budget is spent, so the
// choice is made before each round, from the rounds before it.
//
// Why: on a VM a run is only ever slowed by the host, and on a noisy hour the identity tracer's
// rounds spread 4-11% with one run but 1-3% as the fastest of two of adjacent rounds; 30 rounds
// of one run then leave a scene's ratio several percent from 1.00.
#pragma once

#include <cstddef>
#include <vector>

#include "results/results.h"
#include "runner/scheduler.h"

namespace raygate {

// Runs per program of a `run` scene's next round, from its rounds so far: 1 until it has
// 2 * kMinPairsForSpread one-run rounds (measure/fastest_of_two.h), then 2 where the fastest of
// two is estimated to reach the ratio's precision for at most kFastestOfTwoMustSave of one run's
// seconds. The fastest of two's spread comes from pairs of adjacent one-run rounds, and from the
// repeated rounds' own once there are 2 * kMinPairsForSpread of them; one run's from the one-run
// rounds.
std::size_t ratio_repeats(const std::vector<Round>& rounds_so_far, Role tracer_role,
                          Role baseline_role = Role::baseline);

}  // namespace raygate

// A whole-compare time budget (`--max-minutes`) spent where it decides: scenes are measured one
// after another, each may use what is left divided by the scenes left, so the time a scene saves
// by deciding early goes to the undecided scenes after it.
#pragma once

#include <cstddef>

namespace raygate {

// Seconds the next scene may use: (budget - elapsed) / scenes_left, never below 0; a budget of
// 0 means none (infinity). Throws std::invalid_argument for scenes_left == 0.
double scene_time_share(double budget_seconds, double elapsed_seconds, std::size_t scenes_left);

}  // namespace raygate

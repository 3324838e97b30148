// Every image a scene's runs of one role made: what the Monte Carlo image check summarises (each
// run rendered with its own {seed}, so each image is an independent sample of the picture).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "runner/scheduler.h"

namespace raygate {

// The successful runs' images of `role`: warm-ups, rounds, then the round a failure cut short,
// each image once, in that order (the first is the one the per-pixel check takes).
std::vector<std::filesystem::path> run_images(const SceneRuns& runs, Role role);

}  // namespace raygate

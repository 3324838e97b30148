// Whether a run's image can be judged at all: raygate makes a folder for every run, so a run
// folder that is not there any more was deleted while raygate ran (a cleanup job, a full disk's
// rescue). Nobody can tell what the tracer wrote, so every image check (per pixel or Monte Carlo)
// says the check could not be made (verdict error, exit 3), not that the image is broken (exit 1).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace raygate {

// Why `actual`'s run folder is gone, or nothing (the image or its folder exists, or no image).
std::optional<std::string> vanished_run_folder(const std::filesystem::path& actual);

}  // namespace raygate

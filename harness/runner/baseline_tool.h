// Running raygate-baseline as a child process: one render of one scene, with its image, its
// ray statistics and its process record. Used by golden images, validation and the runner.
#pragma once

#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "core/process.h"

namespace raygate {

struct BaselineOptions {
  std::string accel = "none";       // none | bbox
  std::string sampling = "center";  // center | corners
  std::chrono::milliseconds timeout{std::chrono::minutes(30)};
};

struct BaselineRender {
  ProcessResult process;
  std::filesystem::path image;
  std::filesystem::path stats_path;
  std::filesystem::path log;  // stdout and stderr merged
  nlohmann::json stats;       // parsed --stats output (null if the render failed)
};

class BaselineTool {
 public:
  explicit BaselineTool(std::filesystem::path executable);

  const std::filesystem::path& executable() const { return executable_; }
  // The first line of `raygate-baseline --version`, e.g. "raygate-baseline 0.1.0 source-sha256:…".
  const std::string& version_line() const { return version_line_; }
  // The hex digest after "source-sha256:" in the version line.
  std::string source_hash() const;

  // Renders `scene` to `image`; the stats and log go beside the image. Never throws for a
  // failed render: check process.succeeded().
  BaselineRender render(const std::filesystem::path& scene, const std::filesystem::path& image,
                        const BaselineOptions& options) const;

 private:
  std::filesystem::path executable_;
  std::string version_line_;
};

}  // namespace raygate

// The `--stats FILE.json` document: what was rendered, how much work it took, how long.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

#include "render/render.h"

namespace raygate::render {

struct RunReport {
  std::string version;        // PROJECT_VERSION
  std::string source_sha256;  // hash of the baseline's sources
  std::string scene;          // path as given ("-" for stdin)
  int width = 0;
  int height = 0;
  Sampling sampling = Sampling::center;
  Accel accel = Accel::none;
  int max_depth = 5;
  std::size_t primitives = 0;  // after pp triangulation, degenerate ones dropped
  std::size_t degenerate_primitives = 0;
  std::size_t lights = 0;
  double parse_seconds = 0.0;    // reading and parsing the NFF
  double prepare_seconds = 0.0;  // building primitives and boxes
  double render_seconds = 0.0;   // tracing every ray
  // CPU time (user + system) of this process over parse, prepare and render together: what a
  // harness compares with a tracer it times by CPU seconds (wall time inflates under load).
  double cpu_seconds = 0.0;
  RenderStats stats;
};

nlohmann::json to_json(const RunReport& report);

}  // namespace raygate::render

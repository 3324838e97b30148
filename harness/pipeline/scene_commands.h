// The SPD generators and the scene converters as `raygate scenes` offers them: the list of
// scenes, one scene generated as NFF text, an NFF scene converted for another tracer (POV-Ray,
// OBJ + MTL, pbrt-v4; docs/scene-formats.md). UsageError for anything the user got wrong.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "writers/scene_writers.h"

namespace raygate {

struct SceneRequest {
  std::string name;
  std::optional<int> size;  // nullopt: the scene's own default
  int tessellate = 0;       // 0: curves mode
  std::string resolution;   // "WxH" written into the view; "" = the scene's own
};

struct ConvertRequest {
  std::string input;   // an NFF file
  std::string format;  // pov, obj or pbrt
  std::string output;
  int segments = writers::WriteOptions{}.segments;
};

// {"scenes": [{name, description, default_size, max_size}, ...]}; sizes null where unused.
nlohmann::json scene_list_json();
// One line per scene under a heading: name, default and largest size factor, description.
std::string scene_list_text();

// The scene as NFF text.
std::string generate_scene(const SceneRequest& request);

// Writes the converted files; returns their paths (OBJ writes OUT.mtl beside OUT).
std::vector<std::filesystem::path> convert_scene(const ConvertRequest& request);

}  // namespace raygate

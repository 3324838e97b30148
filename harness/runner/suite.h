// Benchmark suites (scenes/suites/*.json): which SPD scenes, at which size factor and image
// resolution, a run measures. A suite entry is identified by its id ("balls", "tree-s6", ...).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace raygate {

struct SuiteScene {
  std::string id;     // unique within the suite; names golden images and result rows
  std::string scene;  // SPD generator name
  int size = 0;       // SPD size factor (0: the generator's default)
  int width = 0;      // 0: the scene's own resolution
  int height = 0;
};

struct Suite {
  std::string name;
  std::string description;
  std::string sampling = "center";  // baseline sampling: center or corners
  std::vector<SuiteScene> scenes;
  std::filesystem::path path;
};

// `name_or_path` is a suite name (looked up in <data_root>/scenes/suites/NAME.json) or a path to
// a suite file. Unknown keys, wrong types, unknown scenes and bad sizes are UsageErrors naming
// the file and the JSON path.
Suite load_suite(const std::string& name_or_path, const std::filesystem::path& data_root);

// The suite's entries whose id is in `ids` (all when empty); an unknown id is a UsageError.
std::vector<SuiteScene> select_scenes(const Suite& suite, const std::vector<std::string>& ids);

}  // namespace raygate

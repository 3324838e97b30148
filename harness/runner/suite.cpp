#include "runner/suite.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <set>

#include "core/error.h"
#include "core/fs.h"
#include "core/json_reader.h"
#include "core/path_component.h"
#include "spd.h"

namespace raygate {
namespace {

using nlohmann::json;

[[noreturn]] void fail(const Suite& suite, const std::string& where, const std::string& what) {
  throw UsageError(suite.path.string() + ": " + where + ": " + what);
}

void check_keys(const Suite& suite, const json& object, const std::string& where,
                const std::set<std::string>& allowed) {
  for (const auto& [key, value] : object.items()) {
    if (!allowed.contains(key)) fail(suite, where, "unknown key '" + key + "'");
  }
}

// A whole number that fits an int, read without wrapping (1e12 read as an int became
// -727379968, and was reported as that).
int whole_number(const Suite& suite, const json& value, const std::string& where) {
  if (!value.is_number_integer()) fail(suite, where, "expected an integer");
  const bool fits = value.is_number_unsigned()
                        ? value.get<std::uint64_t>() <=
                              static_cast<std::uint64_t>(std::numeric_limits<int>::max())
                        : value.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
                              value.get<std::int64_t>() <= std::numeric_limits<int>::max();
  if (!fits) fail(suite, where, "expected an integer, found " + value.dump() + " (too large)");
  return value.get<int>();
}

int read_int(const Suite& suite, const json& object, const std::string& key,
             const std::string& where) {
  if (!object.contains(key)) return 0;
  return whole_number(suite, object[key], where + "." + key);
}

SuiteScene read_scene(const Suite& suite, const json& entry, const std::string& where) {
  if (!entry.is_object()) fail(suite, where, "expected an object");
  check_keys(suite, entry, where, {"id", "scene", "size", "resolution"});
  SuiteScene s;
  if (!entry.contains("scene") || !entry["scene"].is_string()) {
    fail(suite, where + ".scene", "expected the SPD scene name (a string)");
  }
  s.scene = entry["scene"].get<std::string>();
  const scenes::SceneGenerator* generator = scenes::find_generator(s.scene);
  if (generator == nullptr) fail(suite, where + ".scene", "unknown SPD scene '" + s.scene + "'");
  s.size = read_int(suite, entry, "size", where);
  if (entry.contains("size") && (s.size < 1 || s.size > scenes::max_size(*generator))) {
    fail(suite, where + ".size",
         "size " + std::to_string(s.size) + " out of range 1.." +
             std::to_string(scenes::max_size(*generator)));
  }
  if (entry.contains("resolution")) {
    const json& r = entry["resolution"];
    if (!r.is_array() || r.size() != 2 || !r[0].is_number_integer() || !r[1].is_number_integer()) {
      fail(suite, where + ".resolution", "expected [width, height]");
    }
    s.width = whole_number(suite, r[0], where + ".resolution[0]");
    s.height = whole_number(suite, r[1], where + ".resolution[1]");
    if (s.width < 1 || s.height < 1 || s.width > 16384 || s.height > 16384) {
      fail(suite, where + ".resolution", "each side must be in 1..16384");
    }
    // The baseline renders every suite picture and refuses more than 2^26 pixels (its camera):
    // found only after the build before.
    if (static_cast<long long>(s.width) * s.height > (1LL << 26)) {
      fail(suite, where + ".resolution",
           "at most 2^26 pixels (8192x8192), which the baseline renders too");
    }
  }
  if (entry.contains("id") && !entry["id"].is_string()) {
    fail(suite, where + ".id", "expected a string");
  }
  s.id = entry.contains("id") ? entry["id"].get<std::string>() : s.scene;
  // The id names the scene's files in the cache, run folders and goldens.
  checked_component(s.id, suite.path.string() + ": " + where + ".id");
  return s;
}

std::string scene_ids(const Suite& suite) {
  std::string ids;
  for (const SuiteScene& s : suite.scenes) ids += (ids.empty() ? "" : ", ") + s.id;
  return ids;
}

}  // namespace

Suite load_suite(const std::string& name_or_path, const std::filesystem::path& data_root) {
  Suite suite;
  const bool is_path =
      name_or_path.find('/') != std::string::npos || name_or_path.ends_with(".json");
  suite.path = is_path ? std::filesystem::path(name_or_path)
                       : join_component(data_root / "scenes" / "suites", name_or_path, "suite name",
                                        ".json");
  if (!is_path && !std::filesystem::exists(suite.path)) {
    throw UsageError("unknown suite '" + name_or_path + "' (no " + suite.path.string() + ")");
  }
  json doc = read_json_file(suite.path);  // duplicate keys refused (core/json_reader.h)
  if (!doc.is_object()) fail(suite, "$", "expected an object");
  check_keys(suite, doc, "$", {"name", "description", "sampling", "scenes"});
  // Every optional text checked before it is read: value() of a wrong type throws (found by
  // fuzzing, tests/fuzz/corpus/suite/found-*).
  for (const char* key : {"name", "description", "sampling"}) {
    if (doc.contains(key) && !doc[key].is_string()) {
      fail(suite, std::string("$.") + key, "expected a string");
    }
  }
  suite.name = doc.value("name", suite.path.stem().string());
  // The name names the suite's scene cache folder.
  checked_component(suite.name, suite.path.string() + ": " +
                                    (doc.contains("name") ? "$.name" : "suite name (file stem)"));
  suite.description = doc.value("description", "");
  suite.sampling = doc.value("sampling", "center");
  if (suite.sampling != "center" && suite.sampling != "corners") {
    fail(suite, "$.sampling", "expected \"center\" or \"corners\"");
  }
  if (!doc.contains("scenes") || !doc["scenes"].is_array() || doc["scenes"].empty()) {
    fail(suite, "$.scenes", "expected a non-empty array of scenes");
  }
  std::set<std::string> ids;
  for (std::size_t i = 0; i < doc["scenes"].size(); ++i) {
    const std::string where = "$.scenes[" + std::to_string(i) + "]";
    SuiteScene s = read_scene(suite, doc["scenes"][i], where);
    if (!ids.insert(s.id).second) fail(suite, where + ".id", "duplicate id '" + s.id + "'");
    suite.scenes.push_back(std::move(s));
  }
  return suite;
}

std::vector<SuiteScene> select_scenes(const Suite& suite, const std::vector<std::string>& ids) {
  if (ids.empty()) return suite.scenes;
  std::vector<SuiteScene> out;
  for (const std::string& id : ids) {
    // A document holds a scene once (results_check refuses one listed twice): so does a choice.
    if (std::count(ids.begin(), ids.end(), id) > 1) {
      throw UsageError("scene '" + id.substr(0, 60) + "' is chosen twice; name each scene once");
    }
    bool found = false;
    for (const SuiteScene& s : suite.scenes) {
      if (s.id == id) {
        out.push_back(s);
        found = true;
      }
    }
    if (!found) {
      // A name the user typed, echoed back in a few dozen characters (100,000 were 16 KB).
      const std::string shown =
          id.size() > 60 ? id.substr(0, 60) + "... (" + std::to_string(id.size()) + " characters)"
                         : id;
      throw UsageError("suite '" + suite.name + "' has no scene '" + shown +
                       "'; its scenes: " + scene_ids(suite));
    }
  }
  return out;
}

}  // namespace raygate

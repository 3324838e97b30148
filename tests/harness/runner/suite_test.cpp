// Suite files: the shipped suites load, and broken ones are rejected with the JSON path.
#include "runner/suite.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/fs.h"

namespace raygate {
namespace {

std::string load_error(const std::string& json) {
  TempDir dir;
  const auto path = dir.path() / "bad.json";
  write_file_atomically(path, json);
  try {
    load_suite(path.string(), RAYGATE_SOURCE_DIR);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Suite, ShippedSuitesLoad) {
  for (const char* name : {"ci", "full", "scaling"}) {
    const Suite suite = load_suite(name, RAYGATE_SOURCE_DIR);
    EXPECT_EQ(suite.name, name);
    EXPECT_FALSE(suite.scenes.empty());
  }
}

TEST(Suite, CiCoversEveryScene) {
  const Suite suite = load_suite("ci", RAYGATE_SOURCE_DIR);
  std::set<std::string> scenes;
  for (const SuiteScene& s : suite.scenes) scenes.insert(s.scene);
  EXPECT_EQ(scenes.size(), 13u);
}

TEST(Suite, ErrorsNameTheJsonPath) {
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "ballz"}]})").find("$.scenes[0].scene: unknown SPD scene 'ballz'"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls", "size": 99}]})").find("$.scenes[0].size: size 99 out of range 1..6"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls", "resolution": [0, 5]}]})").find("$.scenes[0].resolution"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls", "colour": 1}]})").find("unknown key 'colour'"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls"}, {"scene": "balls"}]})").find("duplicate id 'balls'"),
            std::string::npos);
  EXPECT_NE(load_error("{not json").find("not valid JSON"), std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": []})").find("$.scenes: expected a non-empty array"),
            std::string::npos);
}

TEST(Suite, UnknownSuiteNameAndSceneSelection) {
  EXPECT_THROW(load_suite("nope", RAYGATE_SOURCE_DIR), UsageError);
  const Suite suite = load_suite("ci", RAYGATE_SOURCE_DIR);
  EXPECT_EQ(select_scenes(suite, {"tetra"}).size(), 1u);
  EXPECT_THROW(select_scenes(suite, {"no-such-scene"}), UsageError);
}

}  // namespace
}  // namespace raygate

// Suite files: the shipped suites load, and broken ones are rejected with the JSON path.
#include "runner/suite.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "core/fs.h"
#include "runner/scene_files.h"

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
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "ballz"}]})")
                .find("$.scenes[0].scene: unknown SPD scene 'ballz'"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls", "size": 99}]})")
                .find("$.scenes[0].size: size 99 out of range 1..6"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls", "resolution": [0, 5]}]})")
                .find("$.scenes[0].resolution"),
            std::string::npos);
  EXPECT_NE(
      load_error(R"({"scenes": [{"scene": "balls", "colour": 1}]})").find("unknown key 'colour'"),
      std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls"}, {"scene": "balls"}]})")
                .find("duplicate id 'balls'"),
            std::string::npos);
  EXPECT_NE(load_error("{not json").find("bad.json:1:"), std::string::npos);
  EXPECT_NE(load_error("{not json").find(": not JSON: syntax error"), std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": []})").find("$.scenes: expected a non-empty array"),
            std::string::npos);
}

// Found by fuzzing (tests/fuzz/corpus/suite/found-sampling-array.json): an optional text of the
// wrong type was an internal error (a type_error from nlohmann), not a usage error.
TEST(Suite, OptionalTextsOfTheWrongTypeAreUsageErrors) {
  for (const char* key : {"name", "description", "sampling"}) {
    const std::string text =
        std::string(R"({")") + key + R"(": [{"corners": 1}], "scenes": [{"scene": "balls"}]})";
    EXPECT_NE(load_error(text).find(std::string("$.") + key + ": expected a string"),
              std::string::npos)
        << key << ": " << load_error(text);
  }
}

// Issue 25: of a key given twice the last won silently, and 1e400 was an internal error.
TEST(Suite, ADuplicateKeyOrAnOutOfRangeNumberIsRefusedWhereItIs) {
  EXPECT_NE(load_error("{\"scenes\": [{\"scene\": \"balls\",\n  \"size\": 1, \"size\": 6}]}")
                .find("bad.json:2:14: $.scenes[0]: duplicate key 'size'"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"name": "a", "name": "b", "scenes": [{"scene": "balls"}]})")
                .find("bad.json:1:15: $: duplicate key 'name'"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls", "resolution": [64, 1e400]}]})")
                .find("$.scenes[0].resolution[1]: number 1e400 is out of range"),
            std::string::npos);
}

// The sweep of 2026-11-28: a size of 10^12 was read as an int and reported as -727379968.
TEST(Suite, AWholeNumberTooLargeForAnIntIsReportedAsGiven) {
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls", "size": 1000000000000}]})")
                .find("$.scenes[0].size: expected an integer, found 1000000000000 (too large)"),
            std::string::npos)
      << load_error(R"({"scenes": [{"scene": "balls", "size": 1000000000000}]})");
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls", "resolution": [64, 4294967360]}]})")
                .find("$.scenes[0].resolution[1]: expected an integer, found 4294967360"),
            std::string::npos);
}

// Ids and names become cache paths (scenes/<suite>/<id>.nff, runs/.../scenes/<id>): one that
// could climb out of the cache is refused at load time, naming the file and the field.
TEST(Suite, IdsAndNamesThatWouldEscapeTheCacheAreRefused) {
  const std::string climbing = load_error(R"({"scenes": [{"scene": "balls", "id": "../x"}]})");
  EXPECT_NE(climbing.find("bad.json: $.scenes[0].id '../x' may hold only letters"),
            std::string::npos)
      << climbing;
  const std::string absolute = load_error(R"({"name": "/tmp/x", "scenes": [{"scene": "balls"}]})");
  EXPECT_NE(absolute.find("bad.json: $.name '/tmp/x' may hold only letters"), std::string::npos)
      << absolute;
  EXPECT_NE(load_error(R"({"name": "..", "scenes": [{"scene": "balls"}]})").find("$.name '..'"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls", "id": ""}]})")
                .find("$.scenes[0].id '' is empty"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"scenes": [{"scene": "balls", "id": 7}]})")
                .find("$.scenes[0].id: expected a string"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"name": 7, "scenes": [{"scene": "balls"}]})")
                .find("$.name: expected a string"),
            std::string::npos);
  try {
    load_suite("..", RAYGATE_SOURCE_DIR);
    ADD_FAILURE() << "suite name '..' accepted";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("suite name '..'"), std::string::npos) << e.what();
  }
}

// A SuiteScene made in code (not loaded) still cannot put its file outside the cache.
TEST(Suite, PreparedSceneFilesStayInTheCache) {
  TempDir cache;
  const SuiteScene ok{"balls-1", "balls", 1, 0, 0};
  EXPECT_EQ(prepare_scene(ok, cache.path()), cache.path() / "balls-1.nff");
  TempDir outside;
  const std::string escape = (outside.path() / "x").string();
  EXPECT_THROW(prepare_scene(SuiteScene{escape, "balls", 1, 0, 0}, cache.path()), UsageError);
  EXPECT_THROW(prepare_scene(SuiteScene{"../x", "balls", 1, 0, 0}, cache.path()), UsageError);
  EXPECT_FALSE(std::filesystem::exists(escape + ".nff"));
  EXPECT_FALSE(std::filesystem::exists(cache.path().parent_path() / "x.nff"));
}

TEST(Suite, UnknownSuiteNameAndSceneSelection) {
  EXPECT_THROW(load_suite("nope", RAYGATE_SOURCE_DIR), UsageError);
  const Suite suite = load_suite("ci", RAYGATE_SOURCE_DIR);
  EXPECT_EQ(select_scenes(suite, {"tetra"}).size(), 1u);
  EXPECT_THROW(select_scenes(suite, {"no-such-scene"}), UsageError);
  // A scene chosen twice would be measured twice into one document, which no reader takes.
  EXPECT_THROW(select_scenes(suite, {"tetra", "tetra"}), UsageError);
  // The sweep of 2026-11-28: a 100,000-character --scene was echoed whole (16 KB).
  try {
    select_scenes(suite, {std::string(100000, 'x')});
    FAIL() << "accepted";
  } catch (const UsageError& e) {
    const std::string message = e.what();
    EXPECT_LT(message.size(), 400u) << message;
    EXPECT_NE(message.find("... (100000 characters)'; its scenes: balls, gears"), std::string::npos)
        << message;
  }
}

}  // namespace
}  // namespace raygate

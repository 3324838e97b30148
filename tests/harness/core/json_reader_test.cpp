// core/json_reader: the one reader of JSON input. A key given twice is refused at the second
// one, with the path of the object and the line and column of the key; a number no double
// holds is refused naming the field; a syntax error says where; anything else parses exactly
// as nlohmann's parser would.
#include <gtest/gtest.h>

#include "core/fs.h"
#include "core/json_reader.h"

namespace raygate {
namespace {

// The message of the JsonInputError that parsing `text` throws, or "" if it parses.
std::string refusal(const std::string& text) {
  try {
    parse_json_input(text, "in.json");
  } catch (const JsonInputError& e) {
    return e.what();
  }
  return "";
}

TEST(JsonReader, ADuplicateKeyIsRefusedWithItsPathLineAndColumn) {
  EXPECT_EQ(refusal("{\"max_slowdown\": 0.03, \"max_slowdown\": 5}"),
            "in.json:1:24: $: duplicate key 'max_slowdown' (JSON keeps only one of them; "
            "remove the other)");
  EXPECT_EQ(refusal("{\n  \"scenes\": {\n    \"balls\": {\"reason\": \"a\",\n"
                    "               \"reason\": \"b\"}}}"),
            "in.json:4:16: $.scenes.balls: duplicate key 'reason' (JSON keeps only one of them; "
            "remove the other)");
  EXPECT_EQ(refusal("{\"a\": [1, {\"x\": 1}, {\"x\": 1, \"x\": 2}]}"),
            "in.json:1:30: $.a[2]: duplicate key 'x' (JSON keeps only one of them; remove the "
            "other)");
  EXPECT_EQ(refusal("{\"odd key\": {\"k\\\"q\": 1, \"k\\\"q\": 2}}"),
            "in.json:1:25: $[\"odd key\"]: duplicate key 'k\"q' (JSON keeps only one of them; "
            "remove the other)");
}

TEST(JsonReader, EqualKeysInDifferentObjectsAreFine) {
  const nlohmann::json parsed =
      parse_json_input(R"({"a": {"x": 1}, "b": {"x": 2}, "c": [{"x": 3}, {"x": 4}]})", "in.json");
  EXPECT_EQ(parsed, nlohmann::json::parse(R"({"a": {"x": 1}, "b": {"x": 2}, "c": [{"x": 3},
                                              {"x": 4}]})"));
}

TEST(JsonReader, ANumberPastADoublesRangeIsAUsageErrorNamingTheField) {
  EXPECT_EQ(refusal("{\"max_slowdown\": 1e400}"),
            "in.json:1:18: $.max_slowdown: number 1e400 is out of range (a double holds "
            "magnitudes up to about 1.8e308)");
  EXPECT_EQ(refusal("{\"scenes\": [{\"size\": 2},\n {\"size\": -2.5E+999}]}"),
            "in.json:2:11: $.scenes[1].size: number -2.5E+999 is out of range (a double holds "
            "magnitudes up to about 1.8e308)");
  EXPECT_EQ(refusal("1e400"),
            "in.json:1:1: $: number 1e400 is out of range (a double holds magnitudes up to "
            "about 1.8e308)");
  const std::string long_number = "{\"n\": 1" + std::string(400, '0') + "}";
  EXPECT_EQ(refusal(long_number),
            "in.json:1:7: $.n: number 1" + std::string(39, '0') +
                "... is out of range (a double holds magnitudes up to about 1.8e308)");
  // Tiny numbers round to zero and huge integers to a double, as JSON allows: not refused.
  EXPECT_EQ(refusal("{\"a\": 1e-400, \"b\": 123456789012345678901234567890}"), "");
}

// A sweep: 20,000 nested arrays in a document's settings crashed import (a recursive walk of the
// document overflowed the stack). Deep nesting is refused where it is, at 128 levels.
TEST(JsonReader, NestingPastAHundredAndTwentyEightLevelsIsRefusedWhereItIs) {
  const auto nested = [](int levels) {
    return "{\"settings\": {\"zzz\": " + std::string(levels, '[') + std::string(levels, ']') + "}}";
  };
  EXPECT_EQ(refusal(nested(126)), "");  // 128 containers with the two objects
  EXPECT_EQ(refusal(nested(127)),
            "in.json:1:148: $.settings.zzz[0][0][0][0]...: nested more than 128 levels deep (no "
            "raygate file nests past about 10)");
  EXPECT_NE(refusal(nested(300000)).find("nested more than 128 levels deep"), std::string::npos);
}

// A sweep: an 8 GB file of NULs given as a results document was read whole (17 GB of memory)
// before it was found not JSON. Past 256 MiB a JSON input is refused by its size, unread.
TEST(JsonReader, AFileOfMoreThan256MiBIsRefusedBeforeItIsRead) {
  TempDir dir;
  const auto sparse = dir.path() / "sparse.json";
  write_file_atomically(sparse, "");
  std::filesystem::resize_file(sparse, std::uintmax_t{8} << 30);  // no blocks: a hole
  try {
    read_json_file(sparse);
    FAIL() << "read";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("sparse.json: is 8192 MiB; raygate reads JSON files of "
                                         "at most 256 MiB"),
              std::string::npos)
        << e.what();
  }
}

TEST(JsonReader, ASyntaxErrorSaysWhereAndIsAUsageError) {
  const std::string message = refusal("{\n  \"a\": 1,\n  \"b\" 2\n}");
  EXPECT_EQ(message.rfind("in.json:3:7: not JSON: syntax error while parsing object separator", 0),
            0u)
      << message;
  EXPECT_THROW(parse_json_input("", "empty.json"), UsageError);
}

TEST(JsonReader, ReadsAFileAndNamesIt) {
  TempDir dir;
  write_file_atomically(dir.path() / "p.json", "{\"a\": 1,\n \"a\": 1}");
  try {
    read_json_file(dir.path() / "p.json");
    ADD_FAILURE() << "the duplicate was taken";
  } catch (const JsonInputError& e) {
    EXPECT_EQ(e.origin(), (dir.path() / "p.json").string());
    EXPECT_EQ(e.line(), 2u);
    EXPECT_EQ(e.column(), 2u);
    EXPECT_EQ(e.json_path(), "$");
  }
  EXPECT_THROW(read_json_file(dir.path() / "missing.json"), UsageError);
}

TEST(JsonReader, PlainTextDropsTheLibrarysLabelOnly) {
  try {
    (void)nlohmann::json::object().at("parse_seconds");
    ADD_FAILURE() << "no exception";
  } catch (const nlohmann::json::exception& e) {
    EXPECT_EQ(plain_exception_text(e), "key 'parse_seconds' not found");
  }
  EXPECT_EQ(plain_exception_text(std::runtime_error("[json.exception.x] y")), "y");
  EXPECT_EQ(plain_exception_text(std::runtime_error("disk full")), "disk full");
  EXPECT_EQ(plain_exception_text(std::runtime_error("[json.exception.no end")),
            "[json.exception.no end");
}

}  // namespace
}  // namespace raygate

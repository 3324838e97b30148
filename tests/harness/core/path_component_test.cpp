// Names that become path components: what is refused, and that the message names the field.
#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "core/path_component.h"

namespace raygate {
namespace {

// The UsageError message for `name`, or "" when it is accepted.
std::string refusal(std::string_view name) {
  try {
    checked_component(name, "scene id");
    return "";
  } catch (const UsageError& e) {
    return e.what();
  }
}

TEST(PathComponent, AcceptsPlainNames) {
  for (const char* name : {"balls", "tree-s6", "cmake_nff", "v1.2", "A", "a..b", ".hidden-ok"}) {
    EXPECT_EQ(checked_component(name, "scene id"), name);
    EXPECT_EQ(component_problem(name), "");
  }
  EXPECT_EQ(checked_component(std::string(kMaxComponentLength, 'x'), "f").size(),
            kMaxComponentLength);
}

TEST(PathComponent, RefusesNamesThatAreNotOneSafeComponent) {
  const std::string nul("a\0b", 3);
  for (const std::string& name :
       {std::string(".."), std::string("."), std::string("../../x"), std::string("/tmp/x"),
        std::string("a/b"), std::string("a\\b"), nul, std::string(""),
        std::string(kMaxComponentLength + 1, 'x'), std::string("sc\xc3\xa8ne"), std::string("a b"),
        std::string("line\nbreak"), std::string("~"), std::string("*")}) {
    EXPECT_NE(refusal(name), "") << "accepted '" << name << "'";
  }
}

TEST(PathComponent, MessageNamesTheFieldAndShowsTheNameVisibly) {
  EXPECT_EQ(refusal("../../x"),
            "scene id '../../x' may hold only letters, digits, '.', '_' and '-' (it becomes a "
            "file or folder name)");
  EXPECT_EQ(refusal(".."), "scene id '..' is a reference to a folder, not a name");
  EXPECT_EQ(refusal(""), "scene id '' is empty");
  EXPECT_NE(refusal(std::string("a\0b", 3)).find("'a\\x00b'"), std::string::npos);
  EXPECT_NE(refusal("sc\xc3\xa8ne").find("'sc\\xc3\\xa8ne'"), std::string::npos);
  EXPECT_NE(refusal(std::string(200, 'x')).find("200 bytes long, more than the 128 allowed"),
            std::string::npos);
}

TEST(PathComponent, JoinAppendsRaygatesSuffixAndNeverEscapes) {
  EXPECT_EQ(join_component("/cache/scenes", "balls", "scene id", ".nff"),
            std::filesystem::path("/cache/scenes/balls.nff"));
  EXPECT_EQ(join_component("/cache", "ci", "suite name"), std::filesystem::path("/cache/ci"));
  EXPECT_THROW(join_component("/cache", "/tmp/x", "suite name"), UsageError);
  EXPECT_THROW(join_component("/cache", "..", "suite name", ".json"), UsageError);
}

}  // namespace
}  // namespace raygate

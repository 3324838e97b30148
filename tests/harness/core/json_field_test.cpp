// core/json_field: a whole number is read only when it is one and lies in the range asked for,
// whatever nlohmann holds it as (a non-negative number is unsigned: 0 must still fail a range
// from 1), and the message says where and what was found.
#include "core/json_field.h"

#include <gtest/gtest.h>

#include <string>

namespace raygate {
namespace {

std::string whole_error(const nlohmann::json& value, std::int64_t lowest, std::int64_t highest) {
  try {
    JsonField(value, "$.n").as_whole(lowest, highest);
    return "";
  } catch (const FieldError& e) {
    return e.path() + ": " + e.what();
  }
}

TEST(JsonField, AWholeNumberIsReadOnlyInItsRange) {
  EXPECT_EQ(JsonField(nlohmann::json(7), "$").as_whole(1, 8), 7);
  EXPECT_EQ(JsonField(nlohmann::json(-3), "$").as_whole(-5, 8), -3);
  EXPECT_EQ(whole_error(0, 1, 8), "$.n: expected a whole number from 1 to 8, found number 0");
  EXPECT_EQ(whole_error(9, 1, 8), "$.n: expected a whole number from 1 to 8, found number 9");
  EXPECT_EQ(whole_error(-6, -5, 8), "$.n: expected a whole number from -5 to 8, found number -6");
  EXPECT_EQ(whole_error(18446744073709551615ULL, 0, 8),
            "$.n: expected a whole number from 0 to 8, found number 18446744073709551615");
  EXPECT_EQ(whole_error(2.5, 1, 8), "$.n: expected a whole number, found number 2.5");
  EXPECT_EQ(whole_error(nlohmann::json::parse("1e20"), 1, 8),
            "$.n: expected a whole number, found number 1e+20");
  EXPECT_EQ(whole_error("8", 1, 8), "$.n: expected a whole number, found string \"8\"");
}

}  // namespace
}  // namespace raygate

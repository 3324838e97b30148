// core/number_text: what is wrong with a number as typed, and what would be right.
#include "core/number_text.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace raygate {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST(NumberText, InRangeDecimalNumbersPass) {
  EXPECT_EQ(number_problem("12", true, 1, 100), "");
  EXPECT_EQ(number_problem("1", true, 1, 100), "");
  EXPECT_EQ(number_problem("100", true, 1, 100), "");
  EXPECT_EQ(number_problem("0.25", false, 0, 1), "");
  EXPECT_EQ(number_problem("1e-3", false, 0, 1), "");
  // The ends as --help prints them: decimal fractions no double holds exactly.
  EXPECT_EQ(number_problem("0.0001", false, 0.0001, 1), "");
  EXPECT_EQ(number_problem("0.001", false, 0.001, 3600), "");
  EXPECT_EQ(number_problem("0.3", false, 0.1, 0.3), "");
}

TEST(NumberText, EachWrongValueIsNamedWithTheRangeThatWouldBeRight) {
  EXPECT_EQ(number_problem("", true, 1, 100000),
            "the value is empty; give a whole number from 1 to 100000");
  EXPECT_EQ(number_problem("ten", false, 0, 1),
            "\"ten\" is not a number; give a number from 0 to 1");
  EXPECT_THAT(number_problem("0x10", true, 1, 100), StartsWith("\"0x10\" is hexadecimal"));
  EXPECT_THAT(number_problem("nan", true, 1, 100), StartsWith("\"nan\" is not a number (NaN)"));
  EXPECT_THAT(number_problem("-inf", false, 0, 1), HasSubstr("not a finite number"));
  EXPECT_THAT(number_problem("1e999", false, 0, 1), HasSubstr("not a finite number"));
  EXPECT_THAT(number_problem("2.5", true, 1, 100), StartsWith("\"2.5\" is not a whole number"));
  // CLI11 reads a count from digits only; these were "Value 1e1 not in range 1 to 100".
  EXPECT_THAT(number_problem("1e1", true, 1, 100), StartsWith("\"1e1\" is not a whole number"));
  EXPECT_THAT(number_problem("5.0", true, 1, 100), StartsWith("\"5.0\" is not a whole number"));
  EXPECT_EQ(number_problem("1e1", false, 1, 100), "");
  EXPECT_EQ(number_problem("0", true, 1, 100),
            "\"0\" is out of range; give a whole number from 1 to 100");
  EXPECT_THAT(number_problem("0.00001", false, 0.0001, 1), HasSubstr("from 0.0001 to 1"));
}

TEST(NumberText, APasteIsQuotedInPart) {
  // 500.000...: out of range, but finite however long it is.
  const std::string problem = number_problem("500." + std::string(99996, '0'), false, 1, 100);
  EXPECT_LT(problem.size(), 200u);
  EXPECT_THAT(problem, HasSubstr("(100000 characters) is out of range"));
}

// CLI11 said "Could not convert" of "1e9" for a count (scenes generate --size).
TEST(NumberText, AWholeNumberIsDigitsOnly) {
  for (const char* whole : {"5", "-5", "+12", "0", ""}) {
    EXPECT_EQ(whole_number_problem(whole), "") << whole;
  }
  EXPECT_THAT(whole_number_problem("0x5"), HasSubstr("is hexadecimal"));  // CLI11 took it as 5
  // The fifth sweep: 20 digits got CLI11's "Could not convert"; 19 are a 64-bit seed's.
  EXPECT_THAT(whole_number_problem("99999999999999999999"), HasSubstr("is past any count"));
  EXPECT_EQ(whole_number_problem("9223372036854775807"), "");
  EXPECT_EQ(whole_number_problem("000000000000000000000042"), "");
  for (const char* not_whole : {"1e9", "2.5", "5.0", "1e0", "2x", "abc", "-", "--5"}) {
    EXPECT_THAT(whole_number_problem(not_whole), HasSubstr("is not a whole number")) << not_whole;
  }
}

TEST(NumberText, SpaceAroundANumberIsNamed) {
  // strtold skips leading space: " 5" was taken by a decimal option and refused by a count.
  EXPECT_EQ(padded_number_problem("5"), "");
  EXPECT_EQ(padded_number_problem(""), "");
  EXPECT_EQ(padded_number_problem(" 5"),
            "\" 5\" has space around the number; give the number alone");
  EXPECT_THAT(padded_number_problem("5\n"), HasSubstr("has space around"));
  EXPECT_THAT(number_problem(" 0.5", false, 0, 1), HasSubstr("has space around"));
  EXPECT_THAT(number_problem("\t3", true, 1, 10), HasSubstr("has space around"));
}

TEST(NumberText, NonFiniteProblemLeavesOtherTextToTheParser) {
  EXPECT_EQ(non_finite_problem("1.5"), "");
  EXPECT_EQ(non_finite_problem("abc"), "");
  EXPECT_EQ(non_finite_problem(""), "");
  EXPECT_THAT(non_finite_problem("NaN"), HasSubstr("NaN"));
}

}  // namespace
}  // namespace raygate

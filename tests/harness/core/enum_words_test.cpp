// An enum's words from one table (core/enum_words.h): both directions agree, a word is matched
// exactly (case and all), and a value missing from the table gets the caller's fallback word.
#include "core/enum_words.h"

#include <gtest/gtest.h>

namespace raygate {
namespace {

enum class Shade { light, dark, unlisted };

constexpr EnumWords<Shade, 2> kShadeWords{{{Shade::light, "light"}, {Shade::dark, "dark-grey"}}};

TEST(EnumWords, EveryValueReadsBackFromItsWord) {
  for (const auto& [value, word] : kShadeWords) {
    EXPECT_EQ(word_of(kShadeWords, value), word);
    EXPECT_EQ(value_of(kShadeWords, word), value);
  }
}

TEST(EnumWords, AnyOtherWordIsNoValue) {
  EXPECT_FALSE(value_of(kShadeWords, "Light").has_value());
  EXPECT_FALSE(value_of(kShadeWords, "dark").has_value());
  EXPECT_FALSE(value_of(kShadeWords, "").has_value());
}

TEST(EnumWords, AValueTheTableLacksGetsTheFallback) {
  EXPECT_EQ(word_of(kShadeWords, Shade::unlisted), "unknown");
  EXPECT_EQ(word_of(kShadeWords, Shade::unlisted, "?"), "?");
  // Usable where the compiler needs the word (a table is constexpr).
  static_assert(word_of(kShadeWords, Shade::dark) == "dark-grey");
  static_assert(value_of(kShadeWords, "light") == Shade::light);
}

}  // namespace
}  // namespace raygate

// The one UTF-8 validator and repairer: what is valid, what each kind of invalid sequence
// becomes, and that valid multibyte text is never touched.
#include <gtest/gtest.h>

#include <string>

#include "core/utf8.h"

namespace raygate {
namespace {

const std::string kFffd(kReplacementCharacter);

TEST(Utf8, ValidTextOfEveryLengthIsKeptByteForByte) {
  // 1, 2, 3 and 4 byte sequences, and the ends of each range.
  for (const std::string& text :
       {std::string(""), std::string("plain ascii"), std::string("caf\xC3\xA9"),
        std::string("\xE2\x82\xAC 5"), std::string("\xF0\x9F\x90\xA2 turtle"),
        std::string("\xC2\x80\xDF\xBF"), std::string("\xE0\xA0\x80\xEF\xBF\xBF"),
        std::string("\xF0\x90\x80\x80\xF4\x8F\xBF\xBF"), std::string("\xED\x9F\xBF"),
        std::string("\xEE\x80\x80"), std::string("nul \0 inside", 12)}) {
    EXPECT_TRUE(is_valid_utf8(text)) << text;
    EXPECT_EQ(repaired_utf8(text), text);
  }
}

TEST(Utf8, AValueThatIsNotTextIsNamedByItsFirstBadByte) {
  EXPECT_EQ(utf8_value_problem("caf\xC3\xA9/x.json"), "");
  EXPECT_EQ(utf8_value_problem("nu\xFF\xFE").substr(0, 31), "not UTF-8 text (byte 0xFF at 3)");
}

TEST(Utf8, OverlongFormsAreInvalidByteByByte) {
  // '/' as 2, 3 and 4 bytes; NUL as C0 80 (Java's "modified UTF-8").
  EXPECT_FALSE(is_valid_utf8("\xC0\xAF"));
  EXPECT_EQ(repaired_utf8("\xC0\xAF"), kFffd + kFffd);
  EXPECT_EQ(repaired_utf8("\xC0\x80"), kFffd + kFffd);
  EXPECT_EQ(repaired_utf8("\xE0\x80\xAF"), kFffd + kFffd + kFffd);
  EXPECT_EQ(repaired_utf8("\xF0\x80\x80\xAF"), kFffd + kFffd + kFffd + kFffd);
  EXPECT_EQ(repaired_utf8("a\xC1\xBFz"), "a" + kFffd + kFffd + "z");
}

TEST(Utf8, SurrogatesAndCodePointsBeyondUnicodeAreInvalid) {
  EXPECT_FALSE(is_valid_utf8("\xED\xA0\x80"));  // U+D800
  EXPECT_EQ(repaired_utf8("\xED\xA0\x80"), kFffd + kFffd + kFffd);
  EXPECT_EQ(repaired_utf8("\xED\xBF\xBF"), kFffd + kFffd + kFffd);  // U+DFFF
  EXPECT_FALSE(is_valid_utf8("\xF4\x90\x80\x80"));                  // U+110000
  EXPECT_EQ(repaired_utf8("\xF4\x90\x80\x80"), kFffd + kFffd + kFffd + kFffd);
  EXPECT_EQ(repaired_utf8("\xF5\x80"), kFffd + kFffd);
  EXPECT_EQ(repaired_utf8("\xFF\xFE"), kFffd + kFffd);
}

TEST(Utf8, TruncatedSequencesBecomeOneReplacementEach) {
  EXPECT_FALSE(is_valid_utf8("\xE2\x82"));
  EXPECT_EQ(repaired_utf8("\xE2\x82"), kFffd);                       // at the end
  EXPECT_EQ(repaired_utf8("\xE2\x82x"), kFffd + "x");                // cut by ASCII
  EXPECT_EQ(repaired_utf8("\xF0\x9F\x90"), kFffd);                   // 3 of 4 bytes
  EXPECT_EQ(repaired_utf8("\xF0\x9F\xC3\xA9"), kFffd + "\xC3\xA9");  // cut by a valid one
  EXPECT_EQ(repaired_utf8("\xC3"), kFffd);
}

TEST(Utf8, StrayContinuationBytesAndLatin1AreReplacedNotDropped) {
  EXPECT_EQ(repaired_utf8("\x80\xBF"), kFffd + kFffd);
  // "Caf\xE9 cr\xE8me" in Latin-1: each lone byte one U+FFFD, the rest kept.
  EXPECT_EQ(repaired_utf8("Caf\xE9 cr\xE8me"), "Caf" + kFffd + " cr" + kFffd + "me");
  EXPECT_TRUE(is_valid_utf8(repaired_utf8(std::string("\xE9\xE8\xFF\x00\xC3", 5))));
}

TEST(Utf8, Latin1DecodesEveryByteToItsCodePoint) {
  EXPECT_EQ(latin1_to_utf8("Caf\xE9 cr\xE8me"), "Caf\xC3\xA9 cr\xC3\xA8me");
  EXPECT_EQ(latin1_to_utf8("\xFF\x80\xA0"), "\xC3\xBF\xC2\x80\xC2\xA0");
  std::string every_byte;
  for (int b = 0; b < 256; ++b) every_byte.push_back(static_cast<char>(b));
  const std::string decoded = latin1_to_utf8(every_byte);
  EXPECT_TRUE(is_valid_utf8(decoded));
  EXPECT_EQ(decoded.size(), 128u + 2u * 128u);
}

TEST(Utf8, SequenceLengthWalksValidTextAndStopsAtInvalid) {
  EXPECT_EQ(utf8_sequence_length("a"), 1u);
  EXPECT_EQ(utf8_sequence_length("\xC3\xA9x"), 2u);
  EXPECT_EQ(utf8_sequence_length("\xE2\x82\xAC"), 3u);
  EXPECT_EQ(utf8_sequence_length("\xF0\x9F\x90\xA2"), 4u);
  EXPECT_EQ(utf8_sequence_length(""), 0u);
  EXPECT_EQ(utf8_sequence_length("\xE9"), 0u);
  EXPECT_EQ(utf8_sequence_length("\xED\xA0\x80"), 0u);
}

}  // namespace
}  // namespace raygate

// Text made safe per output kind: what a terminal and a document (XML, HTML, Markdown) may
// not receive raw.
#include <gtest/gtest.h>

#include <string>

#include "core/sanitize.h"
#include "core/utf8.h"

namespace raygate {
namespace {

TEST(TerminalText, EscapeAndBellSequencesBecomeVisible) {
  // An ESC that would clear the screen and a title-setting OSC ended by BEL.
  EXPECT_EQ(terminal_text("fix\x1b[2J\x1b]0;pwned\x07 done"), "fix\\x1b[2J\\x1b]0;pwned\\x07 done");
  EXPECT_EQ(terminal_text("a\rb\bc\x7f"), "a\\x0db\\x08c\\x7f");
  EXPECT_EQ(terminal_text(std::string("nul\0end", 7)), "nul\\x00end");
}

TEST(TerminalText, C1ControlsAndBidiOverridesBecomeVisible) {
  EXPECT_EQ(terminal_text("\xC2\x9B"
                          "31m"),
            "\\u009b31m");  // CSI as one C1 character
  EXPECT_EQ(terminal_text("\xC2\x85"), "\\u0085");
  EXPECT_EQ(terminal_text("abc\xE2\x80\xAE"
                          "fed"),
            "abc\\u202efed");  // right-to-left override
  EXPECT_EQ(terminal_text("\xE2\x81\xA6x\xE2\x81\xA9"), "\\u2066x\\u2069");
}

TEST(TerminalText, KeepsTabsNewlinesAndPrintableUnicode) {
  const std::string text = "caf\xC3\xA9\t\xE2\x82\xAC 5\n\xF0\x9F\x90\xA2 [+6.1%] <ok> \xC2\xA0";
  EXPECT_EQ(terminal_text(text), text);
}

TEST(TerminalLine, ANewlineIsEscapedTooATabIsKept) {
  EXPECT_EQ(terminal_line("a\tb\ngate: PASS\r\x1b"), "a\tb\\x0agate: PASS\\x0d\\x1b");
}

TEST(TerminalText, RepairsInvalidUtf8First) {
  // A Latin-1 byte 0x9B is not the C1 CSI: it is invalid UTF-8, so it is one U+FFFD. (After
  // \xE9, a 3-byte lead, it would be part of the same invalid sequence: hence the space.)
  const std::string fffd(kReplacementCharacter);
  EXPECT_EQ(terminal_text("Caf\xE9 \x9B[31m"), "Caf" + fffd + " " + fffd + "[31m");
  EXPECT_EQ(terminal_text("Caf\xE9\x9B"), "Caf" + fffd);
}

TEST(MarkupText, EscapesWhatXml10ForbidsAndWhatCannotBeSeen) {
  EXPECT_EQ(markup_text("subject\x1b[31m red\x07"), "subject\\x1b[31m red\\x07");
  EXPECT_EQ(markup_text(std::string("a\0b\x0b\x0c", 5)), "a\\x00b\\x0b\\x0c");
  EXPECT_EQ(markup_text("\xEF\xBF\xBE\xEF\xBF\xBF"), "\\ufffe\\uffff");
  EXPECT_EQ(markup_text("\xC2\x85 \xE2\x80\xAE"
                        "x\x7f"),
            "\\u0085 \\u202ex\\x7f");
  EXPECT_TRUE(is_valid_utf8(markup_text("\xFF\xFE bad")));
}

TEST(MarkupText, KeepsLineEndsTabsAndMarkupForTheWriterToEscape) {
  const std::string allowed = "tab\there\nline\r\n<&> | caf\xC3\xA9 \xC2\xA0 \xF0\x9F\x90\xA2";
  EXPECT_EQ(markup_text(allowed), allowed);
}

}  // namespace
}  // namespace raygate

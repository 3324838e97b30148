// A commit author controls the bytes of a subject: every report kind shows its control
// characters (ESC, BEL, CR, C1, bidi overrides) as visible escapes instead of passing them on,
// and JUnit stays XML 1.0 (no "&#27;", which CI parsers reject).
#include <gtest/gtest.h>

#include <pugixml.hpp>

#include <cctype>
#include <string>

#include "core/utf8.h"
#include "report_fixture.h"

namespace raygate::test {
namespace {

// Clears the screen, sets the window title and rings the bell, returns the carriage to forge
// "PASS" over the line, opens a CSI as one C1 character, reverses what follows, and ends on a
// Latin-1 byte that is not UTF-8.
const std::string kHostileSubject =
    "fix\x1b[2J\x1b]0;owned\x07\rPASS \xC2\x9B"
    "31m \xE2\x80\xAE"
    "dexif caf\xE9";

// The compare fixture with that subject on head and an ESC in the host name.
void make_hostile(Fixture& f) {
  for (RevisionRecord& revision : f.document.revisions) {
    if (revision.role == Role::head) revision.worktree.subject = kHostileSubject;
  }
  f.document.machine["hostname"] = "ci\x1b[8mhidden";
}

// Every ESC in `text` starts one of the reporter's own SGR colour codes ("\x1b[1;31m").
bool only_colour_escapes(const std::string& text) {
  for (std::size_t pos = text.find('\x1b'); pos != std::string::npos;
       pos = text.find('\x1b', pos + 1)) {
    std::size_t end = pos + 1;
    if (end >= text.size() || text[end] != '[') return false;
    ++end;
    while (end < text.size() &&
           (std::isdigit(static_cast<unsigned char>(text[end])) != 0 || text[end] == ';')) {
      ++end;
    }
    if (end >= text.size() || text[end] != 'm') return false;
  }
  return true;
}

// No raw control a terminal or a parser would act on: BEL, CR, C1 CSI, the bidi override.
void expect_no_raw_controls(const std::string& text) {
  EXPECT_EQ(text.find('\x07'), std::string::npos);
  EXPECT_EQ(text.find("\xC2\x9B"), std::string::npos);
  EXPECT_EQ(text.find("\xE2\x80\xAE"), std::string::npos);
  EXPECT_TRUE(is_valid_utf8(text));
}

TEST(ReportControls, ConsoleShowsASubjectsControlsAndKeepsOnlyItsOwnColours) {
  Fixture f(true);
  make_hostile(f);
  const std::string plain = f.render("console", ReportOptions{.colour = false});
  EXPECT_EQ(plain.find('\x1b'), std::string::npos) << plain;
  EXPECT_EQ(plain.find('\r'), std::string::npos);
  expect_no_raw_controls(plain);
  const std::string shown =
      "fix\\x1b[2J\\x1b]0;owned\\x07\\x0dPASS \\u009b31m \\u202edexif caf\xEF\xBF\xBD";
  EXPECT_NE(plain.find(shown), std::string::npos) << plain;
  EXPECT_NE(plain.find("ci\\x1b[8mhidden"), std::string::npos) << plain;

  const std::string coloured = f.render("console", ReportOptions{.colour = true});
  EXPECT_TRUE(only_colour_escapes(coloured)) << coloured;
  EXPECT_NE(coloured.find("\x1b[1;31m"), std::string::npos);  // its own colours still there
  expect_no_raw_controls(coloured);
}

TEST(ReportControls, JunitHasNoCharacterXml10Forbids) {
  Fixture f(true);
  make_hostile(f);
  const std::string xml = f.render("junit");
  for (const char* reference : {"&#27;", "&#7;", "&#0;", "&#155;"}) {
    EXPECT_EQ(xml.find(reference), std::string::npos) << reference << " in\n" << xml;
  }
  for (const char c : xml) {
    const auto byte = static_cast<unsigned char>(c);
    EXPECT_FALSE(byte < 0x20 && c != '\t' && c != '\n' && c != '\r') << static_cast<int>(byte);
  }
  expect_no_raw_controls(xml);
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_string(xml.c_str()));
  bool found = false;
  for (const pugi::xml_node& node :
       doc.child("testsuites").child("testsuite").child("properties").children("property")) {
    const std::string value = node.attribute("value").value();
    if (value.find("fix\\x1b[2J") != std::string::npos) found = true;
  }
  EXPECT_TRUE(found) << xml;
}

TEST(ReportControls, MarkdownShowsControlsAsEscapedText) {
  Fixture f(true);
  make_hostile(f);
  const std::string md = f.render("markdown");
  EXPECT_EQ(md.find('\x1b'), std::string::npos) << md;
  expect_no_raw_controls(md);
  // The escape's backslash is itself escaped, so the comment shows "\x1b[2J".
  EXPECT_NE(md.find("fix\\\\x1b[2J"), std::string::npos) << md;
}

TEST(ReportControls, HtmlShowsControlsAndBidiOverridesAsText) {
  Fixture f(true);
  make_hostile(f);
  const std::string html = f.render("html");
  EXPECT_EQ(html.find('\x1b'), std::string::npos);
  expect_no_raw_controls(html);
  EXPECT_NE(html.find("fix\\x1b[2J\\x1b]0;owned\\x07"), std::string::npos);
  EXPECT_NE(html.find("\\u202edexif"), std::string::npos);
}

}  // namespace
}  // namespace raygate::test

// report/terminal: the last words raygate says are bounded; a long path is shown by its ends.
#include "report/terminal.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

namespace raygate {
namespace {

using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST(BoundedMessage, ShortWordsAreKeptAsTheyAre) {
  const std::string line = "raygate: error: --repo /tmp/x does not exist\n  next line";
  EXPECT_EQ(bounded_message(line), line);
  const std::string edge(240, 'p');
  EXPECT_EQ(bounded_message("a " + edge + " b"), "a " + edge + " b");
}

TEST(BoundedMessage, AWordOverTwoHundredFortyBytesIsShownByItsEnds) {
  // A 6,000-byte --repo path once filled the error line.
  std::string path;
  for (int i = 0; i < 3000; ++i) path += "d/";
  path = "/start" + path + "end";
  const std::string said = bounded_message("repository " + path + " does not exist");
  EXPECT_THAT(said, StartsWith("repository /startd/d/"));
  EXPECT_THAT(said, HasSubstr("…"));
  EXPECT_THAT(said, HasSubstr("d/end (6009 bytes) does not exist"));
  EXPECT_LT(said.size(), 260u);
  EXPECT_THAT(bounded_message(path + ": cannot open"), EndsWith("d/end (6009 bytes): cannot open"));
}

TEST(BoundedMessage, ACutNeverSplitsAUtf8Character) {
  std::string word;
  for (int i = 0; i < 200; ++i) word += "é";  // two bytes each
  const std::string said = bounded_message(word);
  EXPECT_THAT(said, EndsWith("(400 bytes)"));
  // Every byte of the shown ends belongs to a whole "é" or the ellipsis.
  const std::string shown = said.substr(0, said.find(" ("));
  for (std::size_t i = 0; i < shown.size();) {
    if (shown.compare(i, 2, "é") == 0) {
      i += 2;
    } else {
      ASSERT_EQ(shown.compare(i, 3, "…"), 0) << "a cut character at byte " << i;
      i += 3;
    }
  }
}

}  // namespace
}  // namespace raygate

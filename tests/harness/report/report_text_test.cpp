// The reports people read as text: the console table and the Markdown comment carry the
// numbers, put failures first with their reasons, and stay within their limits.
#include <gtest/gtest.h>

#include "report_fixture.h"

namespace raygate::test {
namespace {

std::size_t at(const std::string& text, const std::string& needle) {
  const std::size_t pos = text.find(needle);
  EXPECT_NE(pos, std::string::npos) << "missing '" << needle << "' in:\n" << text;
  return pos;
}

TEST(ConsoleReport, CompareHasNumbersAndFailuresFirst) {
  const Fixture f(true);
  const std::string text = f.render("console");
  at(text, "0.731 -> 0.789");
  at(text, "+7.9% [+6.1%, +9.8%]");
  at(text, "REGRESSED");
  EXPECT_LT(at(text, "\nmount "), at(text, "\ngears "));
  EXPECT_LT(at(text, "\ngears "), at(text, "\ntetra "));
  EXPECT_LT(at(text, "\ntetra "), at(text, "\nballs "));
  // Each failure's reason sits right under its row.
  EXPECT_LT(at(text, "\nmount "), at(text, "- slower: head vs base +7.9%"));
  EXPECT_LT(at(text, "- slower: head vs base +7.9%"), at(text, "\ngears "));
  at(text, "- image head vs golden: max");
  at(text, "killed by SIGSEGV");
  at(text, "raygate: 2 regressions (mount +7.9%, gears image; not measured: tetra; suite +2.6%), "
           "exit 1");
  EXPECT_EQ(text.find('\033'), std::string::npos) << "no colour unless asked";
}

TEST(ConsoleReport, ColourOnlyWhenAsked) {
  const Fixture f(true);
  ReportOptions options;
  options.colour = true;
  const std::string text = f.render("console", options);
  EXPECT_NE(text.find("\033[1;31mFAIL\033[0m"), std::string::npos) << text;
  EXPECT_NE(text.find("\033[32mPASS\033[0m"), std::string::npos) << text;
}

TEST(ConsoleReport, RunShowsRatioWithInterval) {
  const Fixture f(false);
  const std::string text = f.render("console");
  at(text, "ratio [95% CI]");
  at(text, "0.512 [0.508, 0.516]");
  at(text, "MEASURED");
  at(text, "raygate: pass (2 scenes; suite score 0.439), exit 0");
  EXPECT_EQ(text.find("change"), std::string::npos) << "a run has no change column";
}

TEST(MarkdownReport, HeadlineTableAndDetails) {
  const Fixture f(true);
  const std::string text = f.render("markdown");
  EXPECT_EQ(text.rfind("**raygate: 2 regressions** (mount +7.9%, gears image; not measured: "
                       "tetra; suite +2.6%)\n",
                       0),
            0u)
      << text;
  at(text, "| **FAIL** | mount | 0.731 → 0.789 | +7.9% [+6.1%, +9.8%] | REGRESSED | pass |");
  EXPECT_LT(at(text, "| mount |"), at(text, "| gears |"));
  EXPECT_LT(at(text, "| tetra |"), at(text, "| balls |"));
  at(text, "- **mount** (fail): slower: head vs base +7.9%");
  at(text, "<details><summary>Settings, machine and policy</summary>");
  at(text, "- cpu\\_model: `Test CPU @ 3.0GHz`");
  at(text, "</details>");
}

TEST(MarkdownReport, EscapesWhatWouldBreakTheComment) {
  const Fixture f(true);
  const std::string text = f.render("markdown");
  at(text, R"(Use &lt;fast&gt; BVH &amp; "SAH" split)");
  EXPECT_EQ(text.find("<fast>"), std::string::npos);
}

TEST(MarkdownReport, TruncatesToTheLimitWithANote) {
  const Fixture f(true);
  const std::string full = f.render("markdown");
  ReportOptions options;
  options.markdown_limit = full.find("<details>") - 200;
  const std::string text = f.render("markdown", options);
  EXPECT_LE(text.size(), options.markdown_limit);
  at(text, "more scenes not shown");
  at(text, "| mount |");  // failures survive, passes go first
  EXPECT_EQ(text.find("<details>"), std::string::npos);
}

TEST(MarkdownReport, RunSaysPass) {
  const Fixture f(false);
  const std::string text = f.render("markdown");
  EXPECT_EQ(text.rfind("**raygate: pass** (2 scenes; suite score 0.439)\n", 0), 0u) << text;
  at(text, "| **PASS** | balls | 0.512 [0.508, 0.516] | MEASURED | pass |");
}

}  // namespace
}  // namespace raygate::test

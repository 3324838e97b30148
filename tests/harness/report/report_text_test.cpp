// The reports people read as text: the console table and the Markdown comment carry the
// numbers, put failures first with their reasons, and stay within their limits.
#include <gtest/gtest.h>

#include "report/ratio_interval_text.h"

#include "report_fixture.h"

namespace raygate::test {
namespace {

std::size_t occurrences(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (std::size_t pos = text.find(needle); pos != std::string::npos;
       pos = text.find(needle, pos + 1)) {
    ++n;
  }
  return n;
}

// Every scene of the run without a golden, as for a tracer that has none yet.
void without_goldens(Fixture& f) {
  for (SceneResult& scene : f.document.scenes) {
    for (ImageCheck& check : scene.images) {
      check.verdict = ImageVerdict::missing;
      check.error = "no goldens in golden/my-tracer (none blessed yet)";
      check.metrics.reset();
    }
  }
  f.gate = evaluate_gate(f.document, f.policy);
}

std::size_t at(const std::string& text, const std::string& needle) {
  const std::size_t pos = text.find(needle);
  EXPECT_NE(pos, std::string::npos) << "missing '" << needle << "' in:\n" << text;
  return pos;
}

TEST(ConsoleReport, CompareHasNumbersAndFailuresFirst) {
  const Fixture f(true);
  const std::string text = f.render("console");
  at(text, "0.731 -> 0.789");
  // The policy line names the intervals the rows print, not a third confidence.
  at(text,
     "max slowdown +3.0% (within the limit when the 90% CS lies within ±3%, slower when the "
     "decision CS lies above 0, at most 1% false alarms per compare; CS = anytime-valid "
     "confidence sequence, CI = one-look confidence interval; levels: 90% CS = 1 − 2 × the 5% "
     "significance)");
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
  at(text,
     "raygate: 2 regressions (mount +7.9%, gears image; not measured: tetra; suite +2.8%), "
     "exit 1");
  EXPECT_EQ(text.find('\033'), std::string::npos) << "no colour unless asked";
}

// How many runs decided a scene: the rounds that kept the fastest of two are counted in the
// change column of every text report.
TEST(ConsoleReport, SaysHowManyRoundsRanTheFastestOfTwo) {
  Fixture f(true);
  for (SceneResult& scene : f.document.scenes) {
    if (scene.entry.id != "mount") continue;
    for (int k = 0; k < 12; ++k) {
      Round round;
      round.order = k < 7 ? std::vector<std::string>{"base", "head"}
                          : std::vector<std::string>{"base", "head", "base", "head"};
      scene.runs.rounds.push_back(round);
    }
  }
  for (const char* format : {"console", "markdown"}) {
    const std::string text = f.render(format);
    at(text, "12 rounds (5 fastest of 2)");
    EXPECT_EQ(occurrences(text, "fastest of"), 1u) << format << "\n" << text;
  }
}

// `run` chooses the fastest of two per scene too, and its ratio column says so.
TEST(ConsoleReport, ARunSaysHowManyRoundsRanTheFastestOfTwo) {
  Fixture f(false);
  SceneResult& balls = f.document.scenes.front();
  ASSERT_EQ(balls.entry.id, "balls");
  for (int k = 0; k < 12; ++k) {
    Round round;
    round.order = k < 10 ? std::vector<std::string>{"baseline", "tracer"}
                         : std::vector<std::string>{"baseline", "tracer", "baseline", "tracer"};
    balls.runs.rounds.push_back(round);
  }
  for (const char* format : {"console", "markdown", "html"}) {
    const std::string text = f.render(format);
    at(text, "0.512 [0.508, 0.516], 12 rounds (2 fastest of 2)");
    EXPECT_EQ(occurrences(text, "fastest of"), 1u) << format << "\n" << text;
  }
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
  // A run is judged on its images: its policy line does not promise a slowdown limit.
  at(text,
     "policy: images fail when more than 0.02% of pixels differ by over 0.004 in a channel and "
     "warn when fewer do");
  EXPECT_EQ(text.find("max slowdown"), std::string::npos) << text;
}

// The sweep of 2026-11-28: "[-0.7%, +3.0%]" beside UNCHANGED within ±3% (the bound was +2.984%):
// a bound that would print as the limit, or as zero, gets the digits that tell it apart.
TEST(ConsoleReport, ABoundNextToTheLimitIsPrintedWithTheDigitsThatTellItApart) {
  Fixture f(true);
  for (SceneResult& scene : f.document.scenes) {
    if (scene.entry.id == "balls") scene.change->change_interval = {-0.007, 0.02984};
    if (scene.entry.id == "mount") scene.change->change_interval = {0.0004, 0.098};
  }
  const std::string text = f.render("console");
  at(text, "+0.4% [-0.70%, +2.98%]");
  at(text, "+7.9% [+0.04%, +9.80%]");
}

// The sweep of 2026-11-28: one round's ratio was shown as a zero-width "95% CI".
TEST(ConsoleReport, ARatioFromOneRoundHasNoInterval) {
  RatioSummary ratio;
  ratio.ratio = 0.94;
  ratio.ratio_interval = {0.94, 0.94};
  ratio.rounds = 1;
  EXPECT_EQ(ratio_interval_text(ratio), "0.940 (1 round: no interval)");
  ratio.rounds = 2;
  ratio.ratio_interval = {0.9, 0.98};
  EXPECT_EQ(ratio_interval_text(ratio), "0.940 [0.900, 0.980]");
}

// The sweep of 2026-11-28: a Monte Carlo run's policy line printed the per-pixel thresholds,
// while its images were judged within the image tolerance.
TEST(ConsoleReport, AMonteCarloRunsPolicyLineNamesTheRuleItsImagesWereJudgedBy) {
  Fixture f(false);
  f.document.settings.images = ImageKind::monte_carlo;
  f.document.settings.image_tolerance = 0.02;
  const std::string text = f.render("console");
  at(text, "policy: images (Monte Carlo) pass within the ±2% image tolerance");
  EXPECT_EQ(text.find("images fail when"), std::string::npos) << text;
}

// Issue 40: the deciding intervals read 90%, 99.5% and 99.33% with nothing saying why. The
// policy line of every format derives each level from the levels the scenes carry: the
// significance, each scene's share of the compare's false alarms, Holm's larger share.
TEST(Reports, ThePolicyLineSaysWhyEachLevelIsWhatItIs) {
  Fixture f(true);
  f.document.settings.family_significance = 0.01;
  SceneResult* first = nullptr;  // judged after another was found slower: Holm's share
  std::size_t changes = 0;
  for (SceneResult& scene : f.document.scenes) {
    if (!scene.change) continue;
    if (first == nullptr) first = &scene;
    scene.change->interval_kind = ChangeIntervalKind::confidence_sequence;
    scene.change->confidence = 1.0 - 2.0 * 0.01 / (first == &scene ? 3.0 : 4.0);
    scene.change->equivalence_confidence = 0.9;
    ++changes;
  }
  ASSERT_GE(changes, 2u);
  const std::string levels =
      "levels: 90% CS = 1 − 2 × the 5% significance; 99.5% CS = 1 − 2 × 1%/4 (each scene's "
      "share of the 1% over 4 scenes); 99.33% CS for " +
      first->entry.id +
      " = 1 − 2 × 1%/3 (Holm: a larger share once 1 other scene was found slower))";
  at(f.render("console"), levels);
  at(f.render("markdown"), levels);
  at(f.render("junit"), "levels: 90% CS = 1 − 2 × the 5% significance; 99.5% CS");
  // A level that is no share of the family (another raygate's document) is not explained.
  first->change->confidence = 0.97;
  EXPECT_EQ(f.render("console").find("99.5% CS ="), std::string::npos);
}

TEST(ConsoleReport, TheClockLineSaysWhetherIdleCpusWereHeldPolling) {
  Fixture f(true);
  f.document.settings.tracer_clock = "process-cpu";
  f.document.settings.round_cpus = std::vector<int>{0, 1};
  f.document.settings.cpu_idle = CpuIdle::poll;
  at(f.render("console"),
     "clock: process-cpu (measures in seconds); each round pinned to one CPU; idle CPUs held "
     "polling\n");
  f.document.settings.cpu_idle = CpuIdle::os;
  f.document.settings.cpu_idle_refused = "cannot open /dev/cpu_dma_latency: Permission denied";
  at(f.render("console"),
     "clock: process-cpu (measures in seconds); each round pinned to one "
     "CPU; idle CPUs not held polling (cannot open /dev/cpu_dma_latency: "
     "Permission denied)\n");
  // --no-idle-poll, or a document from before: nothing said.
  f.document.settings.cpu_idle_refused.reset();
  EXPECT_EQ(f.render("console").find("idle CPUs"), std::string::npos);
}

TEST(Reports, EveryFormatNamesTheClock) {
  Fixture f(true);
  f.document.settings.tracer_clock = "process-cpu";
  f.document.settings.baseline_clock = "process-cpu";
  f.document.settings.cpu_idle = CpuIdle::poll;
  const std::string clock =
      "process-cpu, baseline process-cpu (measures in seconds); idle CPUs held polling";
  at(f.render("console"), "clock: " + clock + "\n");
  at(f.render("markdown"), "- clock: " + clock + "\n");
  at(f.render("html"), "<dt>clock</dt>");
  at(f.render("html"), clock);
  at(f.render("junit"), "name=\"clock\" value=\"" + clock + "\"");
}

// Issue 40: an adapter's pin_cpus was in the Markdown settings only; the clock line of every
// format says where the runs were pinned and who asked.
TEST(Reports, TheClockLineSaysWhereTheRunsWerePinned) {
  Fixture f(true);
  f.document.settings.tracer_clock = "process-cpu";
  f.document.settings.pin_cpus = std::vector<int>{0};
  f.document.settings.pinned_by = PinnedBy::adapter;
  const std::string adapter =
      "process-cpu (measures in seconds); the tracer pinned to CPU 0 (its adapter's pin_cpus)";
  at(f.render("console"), "clock: " + adapter + "\n");
  at(f.render("markdown"),
     "- clock: process-cpu (measures in seconds); the tracer pinned to CPU 0 (its adapter's "
     "pin\\_cpus)\n");
  at(f.render("html"), "the tracer pinned to CPU 0 (its adapter&#39;s pin_cpus)");
  f.document.settings.pin_cpus = std::vector<int>{2, 3};
  f.document.settings.pinned_by = PinnedBy::option;
  at(f.render("console"),
     "clock: process-cpu (measures in seconds); every run pinned to CPUs 2,3 (--pin)\n");
}

// The unit is the document's (settings.unit), and a counter a mode recorded is printed beside
// the clock with its unit, whatever its name: a new mode's counter needs no report code.
TEST(Reports, EveryFormatPrintsTheUnitAndTheCounters) {
  Fixture f(true);
  f.document.settings.tracer_clock = "instructions";
  f.document.settings.unit = "instructions";
  Round round;
  for (const char* role : {"baseline", "head"}) {
    RunRecord run;
    run.ok = true;
    run.wall_seconds = 2.0;
    run.counters["startup_seconds"] = {0.5, "seconds"};
    run.counters["instructions"] = {2.5e9, "instructions"};
    round.order.emplace_back(role);
    round.runs[role] = run;
  }
  f.document.scenes.front().runs.rounds.push_back(round);
  const std::string console = f.render("console");
  at(console, "clock: instructions (measures in instructions)");
  at(console, "counters: instructions (median per run): baseline 2.5e+09 instructions");
  at(console, "startup_seconds (median per run): baseline 0.500 s");
  at(console, "(25% of its process wall time)");
  at(f.render("markdown"), "- counters: instructions (median per run)");
  at(f.render("html"), "<dt>counters</dt>");
  // Without counters, no line.
  const Fixture plain(true);
  EXPECT_EQ(plain.render("console").find("counters:"), std::string::npos);
}

TEST(MarkdownReport, HeadlineTableAndDetails) {
  const Fixture f(true);
  const std::string text = f.render("markdown");
  EXPECT_EQ(text.rfind("**raygate: 2 regressions** (mount +7.9%, gears image; not measured: "
                       "tetra; suite +2.8%)\n",
                       0),
            0u)
      << text;
  at(text,
     "| **FAIL** | mount | 0.731 → 0.789 | +7.9% [+6.1%, +9.8%] 95% CI, 12 rounds | REGRESSED | pass |");
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
  at(text, R"(Use &lt;fast> BVH &amp; "SAH" split)");  // '<' opens no tag now
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

// A sweep: a 70,000-character commit subject filled GitHub's limit before the scene table, and
// the report was cut inside that line. A subject shows its first line, at most 200 bytes; text
// nothing shortens (a note as long) is cut at the end of a line, with a line saying so.
TEST(MarkdownReport, ALongCommitSubjectLeavesTheTableAndALongNoteIsCutAtALine) {
  Fixture f(true);
  for (RevisionRecord& revision : f.document.revisions) {
    revision.worktree.subject = "fix: " + std::string(70000, 'S') + "\nsecond line";
  }
  std::string text = f.render("markdown");
  EXPECT_LE(text.size(), ReportOptions{}.markdown_limit);
  at(text, "fix: " + std::string(195, 'S') + "…");
  EXPECT_EQ(text.find("second line"), std::string::npos);
  at(text, "| **FAIL** | mount |");
  at(text, "<details>");

  f.gate.notes.push_back("a note " + std::string(70000, 'N'));
  text = f.render("markdown");
  EXPECT_LE(text.size(), ReportOptions{}.markdown_limit);
  EXPECT_EQ(text.rfind("**raygate: 2 regressions**", 0), 0u) << text.substr(0, 200);
  EXPECT_TRUE(text.ends_with(
      "\n_The report was cut here: it would exceed GitHub's comment limit. See the HTML or JSON "
      "report._\n"))
      << text.substr(text.size() - 300);
  EXPECT_EQ(text.find("NNNN"), std::string::npos);  // the long line went whole
}

TEST(MarkdownReport, RunSaysPass) {
  const Fixture f(false);
  const std::string text = f.render("markdown");
  EXPECT_EQ(text.rfind("**raygate: pass** (2 scenes; suite score 0.439)\n", 0), 0u) << text;
  at(text, "| **PASS** | balls | 0.512 [0.508, 0.516], 12 rounds | MEASURED | pass |");
}

TEST(ConsoleReport, NoGoldensIsSaidOnce) {
  Fixture f(false);
  without_goldens(f);
  const std::string text = f.render("console");
  EXPECT_EQ(occurrences(text, "no goldens in golden/my-tracer"), 1u) << text;
  at(text,
     "note: images not checked against goldens: no goldens in golden/my-tracer (none "
     "blessed yet) (2 scenes); look at the images, then bless them: raygate golden bless "
     "--from-run RESULTS.json");
  at(text, "raygate: pass (2 scenes; suite score 0.439), exit 0");
}

// "missing" read as "the image is missing": the column says what it means, in no warning colour.
TEST(ConsoleReport, NoGoldenYetInPlainWords) {
  Fixture f(false);
  without_goldens(f);
  ReportOptions options;
  options.colour = true;
  const std::string text = f.render("console", options);
  at(text, "no golden");
  EXPECT_EQ(text.find("missing"), std::string::npos) << text;
  EXPECT_EQ(text.find("\033[33m"), std::string::npos) << "no amber: " << text;
}

// Reasons keep their arrows: "->" is not a tag and needs no escape.
TEST(MarkdownReport, ArrowsInReasonsStayArrows) {
  const Fixture f(true);
  const std::string text = f.render("markdown");
  EXPECT_EQ(text.find("-&gt;"), std::string::npos) << text;
  at(text, "ratio 0.731 -> 0.789");
}

TEST(ConsoleReport, NoScenesIsNoPass) {
  Fixture f(false);
  f.document.scenes.clear();
  f.gate = evaluate_gate(f.document, f.policy);
  const std::string text = f.render("console");
  at(text, "problem: the document holds no scenes: nothing was measured");
  at(text, "raygate: no scenes (nothing was measured");
  at(text, "exit 3");
}

// The seventh sweep: an undecided change of +1418.9% ended "raygate: pass (1 scene, 1 warning;
// suite +1418.9%)", which a newcomer read as a clean result with a huge change.
TEST(Reports, AnUndecidedChangeIsCalledUndecidedInTheLastLine) {
  Fixture f(true);
  f.document.scenes.resize(1);  // balls alone
  ChangeSummary& change = *f.document.scenes[0].change;
  change.change = 14.189;
  change.change_interval = {-0.5, 30.0};
  f.document.scenes[0].change_verdict = ChangeVerdict::inconclusive;
  f.gate = evaluate_gate(f.document, f.policy);
  for (const char* format : {"console", "markdown"}) {
    at(f.render(format), "(1 scene, 1 undecided; suite +1418.9%, undecided)");
  }
}

TEST(MarkdownReport, NoGoldensIsSaidOnce) {
  Fixture f(false);
  without_goldens(f);
  const std::string text = f.render("markdown");
  EXPECT_EQ(occurrences(text, "no goldens in golden/my-tracer"), 1u) << text;
  at(text, "- note: images not checked against goldens");
  EXPECT_EQ(text.rfind("**raygate: pass** (2 scenes; suite score 0.439)\n", 0), 0u) << text;
  // Under the headline, as in the HTML report, not after the table and the memory section.
  EXPECT_LT(text.find("- note: images not checked"), text.find("<sub>")) << text;
}

// A commit subject is the author's text: Markdown link or image syntax in it stays text.
TEST(MarkdownReport, NeutralisesLinksInCommitSubjects) {
  Fixture f(true);
  for (RevisionRecord& revision : f.document.revisions) {
    revision.worktree.subject = "[click](javascript:alert(1)) ![x](http://t.invalid/p.png)";
  }
  const std::string text = f.render("markdown");
  EXPECT_EQ(text.find("[click]("), std::string::npos) << text;
  EXPECT_EQ(text.find("![x]("), std::string::npos) << text;
  at(text, "[click\\](javascript:alert(1))");
  at(text, "![x\\](http://t.invalid/p.png)");
}

}  // namespace
}  // namespace raygate::test

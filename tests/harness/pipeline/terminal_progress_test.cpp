// pipeline/terminal_progress.cpp: durations as people read them, one rewritten line on a terminal, and only
// plain per-scene lines in CI logs.
#include "pipeline/terminal_progress.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

namespace raygate {
namespace {

TEST(FormatDuration, SecondsMinutesAndHours) {
  EXPECT_EQ(format_duration(0), "0s");
  EXPECT_EQ(format_duration(12.4), "12s");
  EXPECT_EQ(format_duration(59.4), "59s");
  EXPECT_EQ(format_duration(59.6), "1m00s");  // rounded before it is split
  EXPECT_EQ(format_duration(100), "1m40s");
  EXPECT_EQ(format_duration(3599.6), "1h00m");
  EXPECT_EQ(format_duration(7380), "2h03m");
}

TEST(FormatDuration, NegativeIsZero) { EXPECT_EQ(format_duration(-5), "0s"); }

// Everything written to a TerminalProgress, as text.
class ProgressOutput {
 public:
  ProgressOutput() : file_(std::tmpfile(), &std::fclose) {}
  std::FILE* stream() const { return file_.get(); }
  std::string text() const {
    std::fflush(file_.get());
    std::rewind(file_.get());
    std::string out;
    for (int c = std::fgetc(file_.get()); c != EOF; c = std::fgetc(file_.get())) {
      out += static_cast<char>(c);
    }
    return out;
  }

 private:
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
};

ProgressState state_of_round_7() { return {3, 13, "mount", 7, 0.512, 0.008, 100}; }

// What a TerminalProgress wrote by the time it is gone (its destructor clears a line it left).
template <typename Write>
std::string written(bool interactive, Write write) {
  ProgressOutput out;
  {
    TerminalProgress progress(out.stream(), interactive);
    write(progress);
  }
  return out.text();
}

// One progress update on a terminal, then the line cleared.
std::string shown_on_a_terminal(const ProgressState& state) {
  return written(true, [&](TerminalProgress& progress) { progress.update(state); });
}

void round_7_then_done(TerminalProgress& progress) {
  progress.update(state_of_round_7());
  progress.line("[3/13] mount  done");
}

TEST(TerminalProgress, PlainLogsGetOnlyTheFinishedSceneLines) {
  EXPECT_EQ(written(false, round_7_then_done), "[3/13] mount  done\n");
}

TEST(TerminalProgress, TerminalLineIsRewrittenInPlaceAndClearedForSceneLines) {
  EXPECT_EQ(written(true, round_7_then_done),
            "\r\033[K[3/13] mount      round  7  ratio 0.512 ±0.8%  ETA 1m40s"
            "\r\033[K[3/13] mount  done\n");
}

TEST(TerminalProgress, UnknownRatioAndEtaAreLeftOut) {
  EXPECT_EQ(shown_on_a_terminal({1, 2, "balls", 0, 0.0, 0.0, -1.0}),
            "\r\033[K[1/2] balls      round  0\r\033[K");
}

TEST(TerminalProgress, ControlCharactersOfACommitAreShownNotObeyed) {
  // A subject that would clear the screen, set the window title and ring the bell, then a
  // carriage return that would overwrite the line with a forged verdict.
  const std::string text = written(false, [](TerminalProgress& progress) {
    progress.line("  abc1234 fix\x1b[2J\x1b]0;owned\x07\rPASS: 0 failed: 4.0% -> bad");
    progress.status(
        "building def5678 caf\xE9 \xC2\x9B"
        "31m");
  });
  EXPECT_EQ(text,
            "  abc1234 fix\\x1b[2J\\x1b]0;owned\\x07\\x0dPASS: 0 failed: 4.0% -> bad\n"
            "building def5678 caf\xEF\xBF\xBD \\u009b31m\n");
}

TEST(TerminalProgress, TheRewrittenLineKeepsItsOwnEscapesOnly) {
  EXPECT_EQ(shown_on_a_terminal({1, 1, "odd\x1b[8m", 2, 0.0, 0.0, -1.0}),
            "\r\033[K[1/1] odd\\x1b[8m    round  2\r\033[K");  // padded before
}

// A closed terminal fails every write (EIO); so does an unbuffered /dev/full (ENOSPC).
// TerminalProgress is only for whoever watches: it must drop what cannot be shown, never throw,
// least of all from its destructor, which would end raygate with SIGABRT instead of the hang-up's 129.
TEST(TerminalProgress, AStreamThatFailsEveryWriteIsDroppedNotThrown) {
  std::FILE* full = std::fopen("/dev/full", "w");
  ASSERT_NE(full, nullptr);
  std::setvbuf(full, nullptr, _IONBF, 0);
  {
    TerminalProgress progress(full, true);
    EXPECT_NO_THROW(progress.update({1, 2, "tetra", 3, 1.05, 0.01, 12.0}));
    EXPECT_NO_THROW(progress.line("[1/2] tetra  1.050"));
    EXPECT_NO_THROW(progress.update({2, 2, "balls", 1, 0.0, 0.0, -1.0}));
  }  // the destructor clears the rewritten line: it must not throw either
  std::fclose(full);
}

}  // namespace
}  // namespace raygate

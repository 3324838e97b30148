// Failed builds: the first step that exits non-zero, crashes, times out or cannot start ends the
// build; later steps never run, nothing is recorded as usable, the folder is set aside with its
// logs, and the message names the step, what happened, the log and its last lines.
#include <gtest/gtest.h>

#include <fstream>

#include "builder/build_cache.h"
#include "builder/build_steps.h"
#include "builder_fixture.h"
#include "core/error.h"
#include "core/fs.h"

namespace raygate::testing {
namespace {

namespace fs = std::filesystem;

const char* const kThirtyLinesThenFail = "for i in $(seq 1 30); do echo line $i; done; exit 2";

TEST(BuilderFailure, FailingStepStopsTheBuild) {
  BuilderFixture f;
  const Adapter a = toy_adapter(
      {{"touch", "{build}/tracer"}, {"sh", "-c", kThirtyLinesThenFail}, count_step(f.counter())});
  const BuildRecord r = build(f.worktree(), a, f.options());

  EXPECT_FALSE(r.success);
  EXPECT_FALSE(r.cached);
  ASSERT_EQ(r.steps.size(), 2u);
  EXPECT_TRUE(r.steps[0].succeeded);
  EXPECT_FALSE(r.steps[1].succeeded);
  EXPECT_EQ(r.steps[1].outcome, "exited with status 2");
  EXPECT_FALSE(fs::exists(f.counter()));  // step 3 never ran
  EXPECT_FALSE(fs::exists(f.cache() / "builds" / r.key / "build.json"));
  EXPECT_FALSE(fs::exists(f.cache() / "builds" / r.key));
  EXPECT_EQ(r.log_tail.rfind("line 11\n", 0), 0u) << r.log_tail;
  EXPECT_NE(r.log_tail.find("line 30\n"), std::string::npos);
  // The log moved with its folder, and the record says where.
  EXPECT_EQ(r.steps[1].log, f.cache() / "builds" / (r.key + ".failed-1") / "logs" / "step-2.log");
  EXPECT_TRUE(fs::exists(r.steps[1].log));
}

TEST(BuilderFailure, MessageNamesStepOutcomeLogAndTail) {
  BuilderFixture f;
  const BuildRecord r =
      build(f.worktree(), toy_adapter({{"true"}, {"sh", "-c", kThirtyLinesThenFail}}), f.options());
  const std::string message = failure_message(r);
  EXPECT_NE(message.find("step 2 of 2 `sh -c 'for i in $(seq 1 30); do echo line $i; done; "
                         "exit 2'` exited with status 2"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("adapter 'toy', commit aaaaaaaaaaaa"), std::string::npos);
  EXPECT_NE(message.find("log: " + r.steps[1].log.string()), std::string::npos);
  EXPECT_NE(message.find("| line 30"), std::string::npos);
  EXPECT_EQ(message.find("| line 10\n"), std::string::npos);
  try {
    require_success(r);
    FAIL() << "require_success accepted a failed build";
  } catch (const InfraError& e) {
    EXPECT_EQ(e.what(), message);
    EXPECT_EQ(e.code(), ExitCode::infrastructure);
  }
  EXPECT_EQ(failure_message(build(f.worktree(), toy_adapter({}), f.options())), "");
}

// An offline FetchContent configure: the cause is far above the tail, which ends in "Build step
// for googletest failed". The message shows the first error line and the Debian recipe.
TEST(BuilderFailure, MessageShowsTheFirstErrorLineFarAboveTheTail) {
  BuilderFixture f;
  const char* const offline =
      "echo '-- Looking for pthread_create in pthreads - not found'; "
      "echo \"fatal: unable to access 'https://github.com/google/googletest.git/': Could not "
      "resolve host: github.com\"; "
      "for i in $(seq 1 40); do echo retry $i; done; "
      "echo 'CMake Error at googletest-subbuild/CMakeLists.txt: Build step for googletest "
      "failed: 2'; exit 1";
  const BuildRecord r = build(f.worktree(), toy_adapter({{"sh", "-c", offline}}), f.options());
  const std::string message = failure_message(r);
  EXPECT_NE(message.find("first error (line 2 of the log): fatal: unable to access "
                         "'https://github.com/google/googletest.git/': Could not resolve host: "
                         "github.com"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("FETCHCONTENT_SOURCE_DIR_GOOGLETEST=/usr/src/googletest"),
            std::string::npos);
  EXPECT_NE(message.find("| CMake Error at googletest-subbuild"), std::string::npos);
  EXPECT_EQ(message.find("| fatal: unable"), std::string::npos) << "it is not in the tail";
}

// A sweep's build printed a NUL: the error's what() ended there, losing the tail and the hint.
TEST(BuilderFailure, ANulInTheLogIsEscapedAndTheWholeMessageIsKept) {
  BuilderFixture f;
  const BuildRecord r = build(
      f.worktree(), toy_adapter({{"sh", "-c", "printf 'error: a \\000 b\\nsecond\\n'; exit 1"}}),
      f.options());
  try {
    require_success(r);
    FAIL() << "require_success accepted a failed build";
  } catch (const InfraError& e) {
    const std::string what = e.what();  // as main() prints it: up to the first NUL
    EXPECT_NE(what.find("first error (line 1 of the log): error: a \\x00 b"), std::string::npos)
        << what;
    EXPECT_NE(what.find("| second"), std::string::npos) << what;
    EXPECT_NE(what.find("fix the build of this commit"), std::string::npos) << what;
  }
}

TEST(BuilderFailure, FirstErrorLineSkipsCMakeChatter) {
  TempDir dir;
  const fs::path log = dir.path() / "step-1.log";
  write_file_atomically(log,
                        "-- Looking for x - not found\n-- Configuring incomplete, errors "
                        "occurred!\nsrc/a.cpp:3:1: error: 'foo' was not declared\n");
  const std::optional<LogLine> first = first_error_line(log);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->number, 3u);
  EXPECT_EQ(first->text, "src/a.cpp:3:1: error: 'foo' was not declared");
  write_file_atomically(log, "all fine\n");
  EXPECT_FALSE(first_error_line(log).has_value());
  EXPECT_FALSE(first_error_line(dir.path() / "absent.log").has_value());
}

// The executables a build made, for the hint under a wrong run path: CMake's own trees skipped.
TEST(BuilderFailure, BuiltExecutablesAreListedRelativeToTheBuild) {
  TempDir dir;
  const fs::path build_dir = dir.path();
  fs::create_directories(build_dir / "renderer");
  fs::create_directories(build_dir / "CMakeFiles" / "3.25.1" / "CompilerIdCXX");
  for (const fs::path& file : {build_dir / "renderer" / "tracer", build_dir / "notes.txt",
                               build_dir / "CMakeFiles" / "3.25.1" / "CompilerIdCXX" / "a.out",
                               build_dir / "libshade.so"}) {
    write_file_atomically(file, "x");
  }
  for (const fs::path& file : {build_dir / "renderer" / "tracer",
                               build_dir / "CMakeFiles" / "3.25.1" / "CompilerIdCXX" / "a.out",
                               build_dir / "libshade.so"}) {
    fs::permissions(file, fs::perms::owner_exec, fs::perm_options::add);
  }
  EXPECT_EQ(built_executables(build_dir), (std::vector<fs::path>{"renderer/tracer"}));
}

TEST(BuilderFailure, StaleBinaryOfAnotherBuildIsNeverUsed) {
  BuilderFixture f;
  const Adapter good = toy_adapter({{"sh", "-c", "echo old > \"$1/tracer\"", "sh", "{build}"}});
  const BuildRecord old = build(f.worktree(kShaA), good, f.options());
  ASSERT_TRUE(old.success);
  // Same adapter, next commit: the tracer no longer compiles.
  const BuildRecord next = build(f.worktree(kShaB), toy_adapter({{"false"}}), f.options());

  EXPECT_FALSE(next.success);
  EXPECT_NE(next.build_dir, old.build_dir);
  EXPECT_FALSE(fs::exists(next.build_dir / "tracer"));
  EXPECT_THROW(require_success(next), InfraError);
}

TEST(BuilderFailure, RetryOfAFailedKeyStartsEmpty) {
  BuilderFixture f;
  // The first attempt leaves a binary and then fails (the counter has one line); the retry
  // succeeds only if that binary is gone when it starts.
  const Adapter a =
      toy_adapter({{"sh", "-c", "test ! -e \"$1/tracer\"", "sh", "{build}"},
                   count_step(f.counter()),
                   {"touch", "{build}/tracer"},
                   {"sh", "-c", "test \"$(wc -l < \"$1\")\" -ge 2", "sh", f.counter().string()}});
  const BuildRecord first = build(f.worktree(), a, f.options());
  const BuildRecord second = build(f.worktree(), a, f.options());
  EXPECT_FALSE(first.success);
  EXPECT_EQ(first.steps.size(), 4u);
  EXPECT_TRUE(second.success) << failure_message(second);
  EXPECT_FALSE(second.cached);
  EXPECT_EQ(lines_in(f.counter()), 2);
  EXPECT_TRUE(fs::exists(f.cache() / "builds" / (first.key + ".failed-1")));
}

TEST(BuilderFailure, OnlyTheNewestFailedFoldersAreKept) {
  BuilderFixture f;
  const Adapter a = toy_adapter({{"false"}});
  std::string key;
  for (int i = 0; i < 5; ++i) key = build(f.worktree(), a, f.options()).key;
  const fs::path builds = f.cache() / "builds";
  EXPECT_FALSE(fs::exists(builds / (key + ".failed-2")));
  for (const char* n : {"3", "4", "5"}) EXPECT_TRUE(fs::exists(builds / (key + ".failed-" + n)));
}

TEST(BuilderFailure, TimeoutKillsTheStep) {
  BuilderFixture f;
  const Adapter a =
      toy_adapter({{"sleep", "10"}, count_step(f.counter())}, {{"timeout_s", {{"build", 0.3}}}});
  const BuildRecord r = build(f.worktree(), a, f.options());
  EXPECT_FALSE(r.success);
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_LT(r.steps[0].wall_seconds, 3.0);
  EXPECT_NE(r.failure.find("timed out after"), std::string::npos) << r.failure;
  EXPECT_NE(r.failure.find("covers all steps together"), std::string::npos);
  EXPECT_FALSE(fs::exists(f.counter()));
}

TEST(BuilderFailure, OneTimeoutCoversAllSteps) {
  BuilderFixture f;
  // Each step alone fits in the timeout; together they do not, so the second one is stopped.
  const Adapter a =
      toy_adapter({{"sleep", "0.3"}, {"sleep", "0.3"}}, {{"timeout_s", {{"build", 0.5}}}});
  const BuildRecord r = build(f.worktree(), a, f.options());
  EXPECT_FALSE(r.success);
  ASSERT_EQ(r.steps.size(), 2u);
  EXPECT_TRUE(r.steps[0].succeeded);
  EXPECT_EQ(r.steps[1].outcome.rfind("timed out after", 0), 0u) << r.steps[1].outcome;
  EXPECT_LT(r.steps[1].wall_seconds, 0.3);
}

TEST(BuilderFailure, ProgramThatCannotStart) {
  BuilderFixture f;
  const BuildRecord r =
      build(f.worktree(), toy_adapter({{"raygate-no-such-program", "x"}}), f.options());
  EXPECT_FALSE(r.success);
  const std::string message = failure_message(r);
  EXPECT_NE(message.find("`raygate-no-such-program x` could not start: raygate-no-such-program: "
                         "No such file or directory"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("(the log is empty)"), std::string::npos);
}

TEST(BuilderFailure, CrashIsAFailure) {
  BuilderFixture f;
  const BuildRecord r =
      build(f.worktree(), toy_adapter({{"sh", "-c", "kill -SEGV $$"}}), f.options());
  EXPECT_FALSE(r.success);
  EXPECT_NE(r.failure.find("killed by signal 11 (SEGV)"), std::string::npos) << r.failure;
}

TEST(BuilderFailure, MissingSourceFolderFailsWithoutSteps) {
  BuilderFixture f;
  const Adapter a = toy_adapter({count_step(f.counter())}, {{"source_dir", "renderer"}});
  const BuildRecord r = build(f.worktree(), a, f.options());
  EXPECT_FALSE(r.success);
  EXPECT_TRUE(r.steps.empty());
  EXPECT_NE(r.failure.find("renderer does not exist in this commit"), std::string::npos);
  EXPECT_FALSE(fs::exists(f.counter()));
}

TEST(BuilderFailure, MissingPackageFailsBeforeAnyStep) {
  BuilderFixture f;
  const Adapter a = toy_adapter({count_step(f.counter())},
                                {{"requires", {"coreutils", "raygate-no-such-package-xyz"}}});
  try {
    build(f.worktree(), a, f.options());
    FAIL() << "built despite a missing package";
  } catch (const InfraError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("not installed: raygate-no-such-package-xyz"), std::string::npos)
        << message;
    EXPECT_NE(message.find("apt-get install -y raygate-no-such-package-xyz"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(f.counter()));
}

TEST(BuilderSteps, StepAfterTheDeadlineDoesNotStart) {
  BuilderFixture f;
  StepSettings settings;
  settings.working_directory = f.tree();
  settings.logs_dir = f.root() / "logs";
  settings.deadline = std::chrono::steady_clock::now() - std::chrono::seconds(1);
  settings.timeout_seconds = 5;
  const StepsResult r = run_build_steps({{"touch", (f.root() / "ran").string()}}, settings);
  EXPECT_FALSE(r.success);
  ASSERT_EQ(r.steps.size(), 1u);
  EXPECT_EQ(r.failure, "step 1 of 1 `touch " + (f.root() / "ran").string() +
                           "` not started: the steps before it used up the build timeout of 5 s");
  EXPECT_FALSE(fs::exists(f.root() / "ran"));
}

TEST(BuilderSteps, ArgvTextQuotesWhatAShellWouldSplit) {
  EXPECT_EQ(argv_text({"cmake", "-S", "/a/b", "-DX=1"}), "cmake -S /a/b -DX=1");
  EXPECT_EQ(argv_text({"sh", "-c", "a b", "it's", ""}), "sh -c 'a b' 'it'\\''s' ''");
  // An adapter's templates as `raygate adapter check` shows them: placeholders as written, shell
  // syntax quoted.
  EXPECT_EQ(argv_text({"{src}/run.sh", "-o", "{image}", "$HOME", "a*", "~x", "x^y"}),
            "{src}/run.sh -o {image} '$HOME' 'a*' '~x' 'x^y'");
}

}  // namespace
}  // namespace raygate::testing

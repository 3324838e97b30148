// What run and compare say before measuring when a build cannot be used (issue 26, dead ends):
// a run program that is not where the build put it is named once, with the executables the
// build did make; a compare with a side that did not build says how each side did.
#include <gtest/gtest.h>

#include "adapter/adapter.h"
#include "core/error.h"
#include "core/fs.h"
#include "pipeline/revision_setup.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;

Adapter adapter_running(const std::string& program) {
  return parse_adapter(R"({"name": "my-tracer", "scene_format": "nff", "run": [")" + program +
                           R"(", "{scene}", "-o", "{image}"], "image": "{image}"})",
                       "my-tracer.json");
}

std::size_t occurrences(const std::string& text, const std::string& needle) {
  std::size_t n = 0;
  for (auto at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1)) ++n;
  return n;
}

struct Built {
  TempDir dir;
  BuildRecord record;
  Built() {
    record.build_dir = dir.path() / "build";
    record.src_dir = dir.path() / "src";
    record.success = true;
    fs::create_directories(record.build_dir / "renderer");
    write_file_atomically(record.build_dir / "renderer" / "tracer", "#!/bin/sh\n");
    fs::permissions(record.build_dir / "renderer" / "tracer", fs::perms::owner_exec,
                    fs::perm_options::add);
  }
};

TEST(RunProgram, AWrongPathIsNamedOnceWithWhatTheBuildMade) {
  const Built built;
  write_file_atomically(built.record.build_dir / "CMakeCache.txt", "CMAKE_BUILD_TYPE=Release\n");
  try {
    require_run_program(adapter_running("{build}/tracer"), built.record, built.dir.path(), {});
    FAIL() << "a missing run program was accepted";
  } catch (const InfraError& e) {
    const std::string message = e.what();
    EXPECT_EQ(occurrences(message, "tracer does not exist"), 1u) << message;
    EXPECT_EQ(occurrences(message, built.record.build_dir.string()), 0u) << message;
    EXPECT_NE(message.find("the build made these executables:\n    {build}/renderer/tracer"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("add_subdirectory"), std::string::npos);
  }
}

// Issue 40: the CMake hint was printed for a Makefile project too. Only a build folder CMake
// configured (its CMakeCache.txt) gets it.
TEST(RunProgram, TheCMakeHintIsForACMakeBuildOnly) {
  const Built built;  // no CMakeCache.txt: a Makefile's build
  try {
    require_run_program(adapter_running("{build}/tracer"), built.record, built.dir.path(), {});
    FAIL() << "a missing run program was accepted";
  } catch (const InfraError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.find("CMake"), std::string::npos) << message;
    EXPECT_EQ(message.find("add_subdirectory"), std::string::npos) << message;
    EXPECT_NE(message.find("fixing `run` reuses this build"), std::string::npos) << message;
  }
}

TEST(RunProgram, TheRightPathAPathOnPathAndARunTimePathPass) {
  const Built built;
  EXPECT_NO_THROW(require_run_program(adapter_running("{build}/renderer/tracer"), built.record,
                                      built.dir.path(), {}));
  EXPECT_NO_THROW(
      require_run_program(adapter_running("povray"), built.record, built.dir.path(), {}));
  EXPECT_NO_THROW(
      require_run_program(adapter_running("{workdir}/tracer"), built.record, built.dir.path(), {}));
}

TEST(BothSides, AFailedSideIsReportedWithHowTheOtherDid) {
  BuildRecord base;
  base.success = true;
  base.sha = std::string(40, 'a');
  BuildRecord head;
  head.sha = std::string(40, 'b');
  head.adapter_name = "my-tracer";
  head.failure = "step 1 of 2 `cmake ...` exited with status 1";
  EXPECT_NO_THROW(require_both_built(base, base));
  try {
    require_both_built(base, head);
    FAIL() << "a failed head was accepted";
  } catch (const InfraError& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("base (aaaaaaaaaaaa) built\nhead did not build:\nbuild failed", 0), 0u)
        << message;
  }
  BuildRecord broken_base = head;
  broken_base.sha = base.sha;
  try {
    require_both_built(broken_base, head);
    FAIL();
  } catch (const InfraError& e) {
    EXPECT_EQ(occurrences(e.what(), "did not build"), 2u) << e.what();
  }
}

// --worktree is the user's argument: a folder that is not there, or a --rev beside it that would
// silently not be measured, is refused before anything is built (exit 2, not a failed build).
TEST(RunTree, AMissingWorktreeOrARevBesideItIsAUsageError) {
  const TempDir dir;
  try {
    locate_run_tree(".", "HEAD", (dir.path() / "nowhere").string(), dir.path());
    ADD_FAILURE() << "a missing worktree was taken";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("nowhere: no such folder"), std::string::npos) << e.what();
  }
  try {
    locate_run_tree(".", "HEAD~3", dir.path().string(), dir.path());
    ADD_FAILURE() << "--rev beside --worktree was taken";
  } catch (const UsageError& e) {
    EXPECT_NE(std::string(e.what()).find("--rev HEAD~3 and --worktree"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace raygate

// An interrupted build (SIGINT or SIGTERM while a step runs) never leaves a cache entry that
// looks complete, even when the step finishes cleanly on the signal; its step's processes are
// gone, and the next build of the key runs the steps again.
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <thread>

#include "builder/build_cache.h"
#include "builder_fixture.h"
#include "core/interrupt.h"

namespace raygate::testing {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

class BuilderInterrupt : public ::testing::Test {
 protected:
  BuilderInterrupt() { install_interrupt_handlers(); }
  ~BuilderInterrupt() override { clear_interrupt_for_testing(); }

  // A step that counts its runs and, unless `go` exists, writes its pid and waits; on SIGTERM
  // it finishes its output and exits 0, as a build tool that cleans up would. The script uses
  // no braces: the adapter would expand "{...}" as one of its own placeholders ({src}, {build}).
  Adapter waiting_adapter() const {
    const std::string script =
        "echo ran >> \"$1\"; trap 'touch \"$4\"/tracer; exit 0' TERM; "
        "if [ ! -e \"$2\" ]; then echo $$ > \"$3\"; while :; do sleep 0.05; done; fi; "
        "touch \"$4\"/tracer";
    return toy_adapter({{"sh", "-c", script, "sh", f_.counter().string(), go().string(),
                         pid_file().string(), "{build}"}});
  }
  fs::path go() const { return f_.root() / "go"; }
  fs::path pid_file() const { return f_.root() / "step.pid"; }

  BuilderFixture f_;
};

TEST_F(BuilderInterrupt, InterruptedBuildLeavesNothingThatLooksCompleteAndIsBuiltAgain) {
  const Adapter adapter = waiting_adapter();
  std::thread stopper([&] {
    for (int i = 0; i < 500 && !fs::exists(pid_file()); ++i) std::this_thread::sleep_for(10ms);
    request_interrupt(SIGINT);
  });
  std::string key;
  try {
    build(f_.worktree(), adapter, f_.options());
    ADD_FAILURE() << "the interrupted build returned";
  } catch (const Interrupted& e) {
    EXPECT_EQ(to_int(e.code()), 130);
    const std::string message = e.what();
    EXPECT_NE(message.find("interrupted by SIGINT"), std::string::npos) << message;
    EXPECT_NE(message.find("the unfinished build was removed"), std::string::npos) << message;
  }
  stopper.join();
  ASSERT_EQ(lines_in(f_.counter()), 1);
  // Neither a record nor any of the half-built files are left for a later run to find.
  for (const auto& entry : fs::recursive_directory_iterator(f_.cache() / "builds")) {
    EXPECT_NE(entry.path().filename(), "build.json") << entry.path();
    EXPECT_NE(entry.path().filename(), "tracer") << entry.path();
  }

  clear_interrupt_for_testing();
  write_file_atomically(go(), "");
  const BuildRecord again = build(f_.worktree(), adapter, f_.options());
  EXPECT_TRUE(again.success) << again.failure;
  EXPECT_FALSE(again.cached);
  EXPECT_EQ(lines_in(f_.counter()), 2);  // the step ran again
  EXPECT_TRUE(build(f_.worktree(), adapter, f_.options()).cached);
}

}  // namespace
}  // namespace raygate::testing

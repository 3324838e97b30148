// runner/idle_poll.h: the PM QoS request is a 32-bit zero written to the device and held for
// as long as the hold lives; a machine that refuses it leaves the hold empty with the reason.
// A regular file stands in for /dev/cpu_dma_latency, so the test needs no root and changes no
// idle state.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "runner/idle_poll.h"

namespace raygate {
namespace {

namespace fs = std::filesystem;

class IdlePollTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("raygate-idle-poll-" + std::to_string(::getpid()) + "-" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    device_ = dir_ / "cpu_dma_latency";
    std::ofstream(device_).flush();
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::vector<char> device_bytes() const {
    std::ifstream in(device_, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  fs::path dir_;
  fs::path device_;
};

std::size_t open_descriptors() {
  std::size_t count = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator("/proc/self/fd")) ++count;
  return count;
}

TEST_F(IdlePollTest, WritesALatencyOfZeroAndHoldsTheFileOpenUntilItEnds) {
  const std::size_t before = open_descriptors();
  {
    const IdlePollHold hold(device_);
    EXPECT_TRUE(hold.held());
    EXPECT_EQ(hold.why_not(), "");
    EXPECT_EQ(open_descriptors(), before + 1);
    EXPECT_EQ(device_bytes(), std::vector<char>(sizeof(std::int32_t), '\0'));
  }
  // The kernel drops the request when the file is closed: nothing outlives the hold.
  EXPECT_EQ(open_descriptors(), before);
}

TEST_F(IdlePollTest, AMachineThatRefusesLeavesItUnheldWithTheReason) {
  const fs::path missing = dir_ / "no-such-dir" / "cpu_dma_latency";
  const IdlePollHold hold(missing);
  EXPECT_FALSE(hold.held());
  EXPECT_EQ(hold.why_not(), "cannot open " + missing.string() + ": No such file or directory");

  // A directory cannot be opened for writing either (EISDIR), root or not.
  const IdlePollHold on_directory(dir_);
  EXPECT_FALSE(on_directory.held());
  EXPECT_NE(on_directory.why_not().find("Is a directory"), std::string::npos)
      << on_directory.why_not();
}

// Issue 40: the kernel's device (here /dev/null, a character device that takes the write) holds
// idle CPUs polling only with a cpuidle driver; with "none" (many VMs) the record must not say
// "poll", so the hold is not taken, with the reason.
TEST_F(IdlePollTest, TheKernelsRequestIsHeldOnlyWithACpuidleDriver) {
  const fs::path driver = dir_ / "current_driver";
  std::ofstream(driver) << "none\n";
  const IdlePollHold without(fs::path("/dev/null"), driver);
  EXPECT_FALSE(without.held());
  EXPECT_EQ(without.why_not(), "no cpuidle driver (" + driver.string() +
                                   ": none): idle CPUs halt whatever latency is asked");
  const IdlePollHold unreadable(fs::path("/dev/null"), dir_ / "missing");
  EXPECT_FALSE(unreadable.held());
  std::ofstream(driver) << "intel_idle\n";
  const IdlePollHold with(fs::path("/dev/null"), driver);
  EXPECT_TRUE(with.held()) << with.why_not();
}

TEST_F(IdlePollTest, AMovedHoldIsReleasedOnceByItsNewOwner) {
  const std::size_t before = open_descriptors();
  {
    IdlePollHold first(device_);
    IdlePollHold second(std::move(first));
    EXPECT_TRUE(second.held());
    EXPECT_FALSE(first.held());  // NOLINT(bugprone-use-after-move): moved-from is defined empty
    IdlePollHold third(dir_ / "missing");
    third = std::move(second);
    EXPECT_TRUE(third.held());
    EXPECT_EQ(open_descriptors(), before + 1);
  }
  EXPECT_EQ(open_descriptors(), before);
}

}  // namespace
}  // namespace raygate

// adapter/timing_regex: an adapter's timing.regex is matched with a bound. A sweep's `^(a+)+$`
// against 37 characters spun std::regex for ever (deaf to SIGTERM), and 20,000 nested groups
// overflowed its stack while compiling; here both end in words, at once.
#include "adapter/timing_regex.h"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "adapter/adapter.h"
#include "adapter/reported_time.h"

namespace raygate {
namespace {

TEST(TimingRegex, FindsTheFirstGroupOrSaysItDidNotMatch) {
  const TimingRegex re("render time: ([0-9.]+) ms");
  EXPECT_EQ(re.capture_groups(), 1u);
  const auto found = re.first_group("frame 3: render time: 12.5 ms");
  ASSERT_TRUE(found && *found);
  EXPECT_EQ(**found, "12.5");
  EXPECT_FALSE(re.first_group("no time here"));
  const TimingRegex optional_group("done(?: in ([0-9]+) s)?");
  const auto unset = optional_group.first_group("done");
  ASSERT_TRUE(unset);
  EXPECT_FALSE(*unset);
}

TEST(TimingRegex, ExponentialBacktrackingStopsAtTheBoundWithWords) {
  const TimingRegex re("^(a+)+$");
  const auto started = std::chrono::steady_clock::now();
  try {
    (void)re.first_group(std::string(36, 'a') + "b");
    FAIL() << "the match was not bounded";
  } catch (const RegexTooCostly& e) {
    EXPECT_NE(std::string(e.what()).find("more than 200000 steps"), std::string::npos) << e.what();
  }
  EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(5));
}

TEST(TimingRegex, DeepNestingIsACompileErrorNotACrash) {
  std::string pattern = "(";
  for (int i = 0; i < 20000; ++i) pattern += "(?:";
  pattern += "[0-9.]+";
  pattern += std::string(20001, ')');
  const auto error = reported_regex_error(pattern);
  ASSERT_TRUE(error);
  EXPECT_NE(error->find("does not compile: "), std::string::npos) << *error;
  EXPECT_NE(reported_regex_error("a(b"), std::nullopt);
  EXPECT_EQ(reported_regex_error("Time: (\\d+:\\d+\\.\\d+)"), std::nullopt);
  EXPECT_NE(reported_regex_error("(a)(b)")->find("exactly one capture group"), std::string::npos);
}

}  // namespace
}  // namespace raygate

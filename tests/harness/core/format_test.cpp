// How raygate prints fractions, durations and counts (core/format.h): one formatter, so the
// console, the reports and the gate's reasons read alike, and a count of one is singular.
#include <gtest/gtest.h>

#include <limits>

#include "core/format.h"

namespace raygate {
namespace {

TEST(Format, PercentsShowTheSignOfAChangeAndSayWhenThereIsNoNumber) {
  EXPECT_EQ(percent(0.079), "7.9%");
  EXPECT_EQ(signed_percent(0.079), "+7.9%");
  EXPECT_EQ(signed_percent(-0.02, 2), "-2.00%");
  EXPECT_EQ(signed_percent(std::numeric_limits<double>::quiet_NaN()), "n/a");
}

TEST(Format, DurationsUseTheUnitAPersonReads) {
  EXPECT_EQ(duration_text(40.2), "40 s");
  EXPECT_EQ(duration_text(-1.0), "0 s");
  EXPECT_EQ(duration_text(180.0), "3 min");
  EXPECT_EQ(duration_text(9000.0), "2.5 h");
}

TEST(Format, ACountOfOneIsSingular) {
  EXPECT_EQ(count_text(1, "round"), "1 round");
  EXPECT_EQ(count_text(0, "round"), "0 rounds");
  EXPECT_EQ(count_text(17, "round"), "17 rounds");
  EXPECT_EQ(count_text(2, "process", "processes"), "2 processes");
  EXPECT_EQ(count_text(1, "process", "processes"), "1 process");
}

}  // namespace
}  // namespace raygate

// core/time_text: the times documents carry are real times, as raygate and git write them.
#include "core/time_text.h"

#include <gtest/gtest.h>

#include <string>

namespace raygate {
namespace {

TEST(TimeText, WhatRaygateAndGitWriteIsATime) {
  EXPECT_TRUE(is_iso8601_time(utc_timestamp()));
  for (const char* time :
       {"2026-11-29T14:37:00Z", "2026-11-29T14:37:00+02:00", "2026-11-29T14:37:00-0130",
        "2024-02-29T23:59:60Z", "2026-01-02T03:04:05.250Z", "2026-01-02T03:04:05"}) {
    EXPECT_TRUE(is_iso8601_time(time)) << time;
  }
}

// merge keeps the earliest start by comparing the texts: what is not a time would sort anywhere.
TEST(TimeText, WhatIsNoRealTimeIsRefused) {
  for (const char* text :
       {"yesterday", "", "2026-02-30T10:00:00Z", "2025-02-29T10:00:00Z", "2026-13-01T10:00:00Z",
        "2026-11-29T25:61:00Z", "2026-11-29 14:37:00Z", "2026-11-29T14:37:00+25:00",
        "2026-11-29T14:37:00.Z", "2026-11-29T14:37:00Zjunk", "2026-1-29T14:37:00Z"}) {
    EXPECT_FALSE(is_iso8601_time(text)) << text;
  }
  EXPECT_FALSE(is_iso8601_time(std::string(100000, '1')));
}

// A document's finished_at is checked to follow its started_at, whatever zones the two are in.
TEST(TimeText, ATimeIsSecondsSinceTheEpochWithItsZoneApplied) {
  EXPECT_EQ(iso8601_epoch_seconds("1970-01-01T00:00:00Z"), 0.0);
  EXPECT_EQ(iso8601_epoch_seconds("2000-03-01T00:00:00Z"), 951868800.0);  // after a leap day
  EXPECT_EQ(iso8601_epoch_seconds("2026-11-29T14:37:00Z"), 1795963020.0);
  EXPECT_EQ(iso8601_epoch_seconds("2026-11-29T16:37:00+02:00"), 1795963020.0);
  EXPECT_EQ(iso8601_epoch_seconds("2026-11-29T13:07:00-0130"), 1795963020.0);
  EXPECT_EQ(iso8601_epoch_seconds("2026-11-29T14:37:00.25Z"), 1795963020.25);
  EXPECT_EQ(iso8601_epoch_seconds("1969-12-31T23:59:59Z"), -1.0);
  EXPECT_EQ(iso8601_epoch_seconds("2026-02-30T10:00:00Z"), std::nullopt);
}

}  // namespace
}  // namespace raygate

// "Did you mean" (core/suggest.h): the distance counts a swap of two letters as one typo, and
// only a plausible typo is suggested.
#include <gtest/gtest.h>

#include "core/suggest.h"

namespace raygate {
namespace {

TEST(Suggest, EditDistanceCountsATranspositionOnce) {
  EXPECT_EQ(edit_distance("tiemout_s", "timeout_s"), 1);
  EXPECT_EQ(edit_distance("", "abc"), 3);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
  EXPECT_EQ(closest_match("scen", {"src", "scene", "scene_stem"}), "scene");
  EXPECT_EQ(closest_match("colour", {"name", "run"}), std::nullopt);
}

}  // namespace
}  // namespace raygate

// An image verdict's word reads back as the same verdict, an unknown word as none, and the
// enum's order is the rank the gate takes the worst of.
#include "compare/image_verdict.h"

#include <gtest/gtest.h>

namespace raygate {
namespace {

constexpr ImageVerdict kAll[] = {ImageVerdict::missing, ImageVerdict::pass,
                                 ImageVerdict::warn,    ImageVerdict::inconclusive,
                                 ImageVerdict::error,   ImageVerdict::fail};

TEST(ImageVerdict, EveryVerdictReadsBackFromItsWord) {
  for (const ImageVerdict verdict : kAll) {
    EXPECT_EQ(parse_image_verdict(to_string(verdict)), verdict) << to_string(verdict);
  }
  EXPECT_EQ(to_string(ImageVerdict::missing), "missing");
  EXPECT_EQ(to_string(ImageVerdict::fail), "fail");
  EXPECT_EQ(to_string(ImageVerdict::inconclusive), "inconclusive");
}

TEST(ImageVerdict, AnUnknownWordIsNoVerdict) {
  for (const char* word : {"", "FAIL", "passed", "none"}) {
    EXPECT_EQ(parse_image_verdict(word), std::nullopt) << word;
  }
}

// A missing golden ranks lowest, a found difference highest (gate/verdict.cpp takes the max).
TEST(ImageVerdict, OrderIsTheRank) {
  for (std::size_t i = 1; i < std::size(kAll); ++i) EXPECT_LT(kAll[i - 1], kAll[i]);
}

}  // namespace
}  // namespace raygate

// pipeline/render_time: the line through two timed renders, and the resolution it picks.
#include "pipeline/render_time.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace raygate {
namespace {

TEST(RenderTime, FitsTheFixedAndPerPixelParts) {
  // 0.5 s fixed, 1e-4 s a pixel: 64x64 takes 0.9096 s, 128x128 2.1384 s.
  const RenderTimeModel model = fit_render_time({64, 64, 0.9096}, {128, 128, 2.1384});
  EXPECT_NEAR(model.fixed_seconds, 0.5, 1e-9);
  EXPECT_NEAR(model.seconds_per_pixel, 1e-4, 1e-12);
  // Either order of the two renders.
  const RenderTimeModel swapped = fit_render_time({128, 128, 2.1384}, {64, 64, 0.9096});
  EXPECT_NEAR(swapped.fixed_seconds, 0.5, 1e-9);
}

TEST(RenderTime, NoiseNeverMakesAPartNegative) {
  // The smaller render slower than the larger: every second is fixed.
  const RenderTimeModel flat = fit_render_time({64, 64, 1.2}, {128, 128, 1.0});
  EXPECT_EQ(flat.seconds_per_pixel, 0.0);
  EXPECT_DOUBLE_EQ(flat.fixed_seconds, 1.0);
  // A line that would cross zero pixels below zero seconds: through the origin instead.
  const RenderTimeModel steep = fit_render_time({64, 64, 0.1}, {128, 128, 1.6});
  EXPECT_EQ(steep.fixed_seconds, 0.0);
  EXPECT_DOUBLE_EQ(steep.seconds_per_pixel, 1.6 / (128.0 * 128.0));
}

TEST(RenderTime, RefusesRendersItCannotFitALineThrough) {
  EXPECT_THROW(fit_render_time({64, 64, 1.0}, {64, 64, 2.0}), std::invalid_argument);
  EXPECT_THROW(fit_render_time({0, 64, 1.0}, {64, 64, 2.0}), std::invalid_argument);
}

TEST(RenderTime, ChoosesTheResolutionThatTakesTheTarget) {
  const RenderTimeModel model{0.5, 1e-4};
  // 1.5 s: 10,000 pixels at 1e-4 beyond the fixed 0.5 s -> 100x100 of a square picture.
  const ChosenResolution square = choose_resolution(model, 128, 128, 1.5, 16);
  EXPECT_EQ(square.width, 100);
  EXPECT_EQ(square.height, 100);
  EXPECT_NEAR(square.predicted_seconds, 1.5, 1e-9);
  EXPECT_TRUE(square.reached);
  // The aspect is kept: 2:1 at 10,000 pixels is about 141x71.
  const ChosenResolution wide = choose_resolution(model, 256, 128, 1.5, 16);
  EXPECT_EQ(wide.width, 141);
  EXPECT_EQ(wide.height, 71);
  EXPECT_TRUE(wide.reached);
}

TEST(RenderTime, SaysWhenTheTargetCannotBeReached) {
  // The fixed part alone is over the target: the smallest picture, not reached.
  const ChosenResolution slow = choose_resolution({2.0, 1e-4}, 128, 128, 1.0, 16);
  EXPECT_EQ(slow.width, 16);
  EXPECT_EQ(slow.height, 16);
  EXPECT_FALSE(slow.reached);
  EXPECT_NEAR(slow.predicted_seconds, 2.0 + 256e-4, 1e-9);
  // A target that needs more than the largest side.
  const ChosenResolution big = choose_resolution({0.0, 1e-9}, 128, 128, 100.0, 16, 1024);
  EXPECT_EQ(big.width, 1024);
  EXPECT_FALSE(big.reached);
  EXPECT_THROW(choose_resolution({0.5, 1e-4}, 128, 128, 0.0, 16), std::invalid_argument);
  EXPECT_THROW(choose_resolution({0.5, 1e-4}, 128, 128, -1.0, 16), std::invalid_argument);
}

}  // namespace
}  // namespace raygate

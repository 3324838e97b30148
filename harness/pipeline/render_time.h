// How a tracer's render time grows with the picture's pixels, fitted from two timed renders of
// one scene, and the resolution at which a render takes a target time (raygate calibrate,
// pipeline/calibrate.h). The model is a line: a fixed part (start-up, parsing, building the
// acceleration structure, writing the image) that no resolution changes, and a part per pixel.
#pragma once

#include <string>

namespace raygate {

struct TimedRender {
  int width = 0;
  int height = 0;
  double seconds = 0.0;        // wall seconds, as the budget counts them
  double timed_seconds = 0.0;  // the seconds the ratio uses (the adapter's clock: CPU, ...)

  double pixels() const { return static_cast<double>(width) * static_cast<double>(height); }
};

struct RenderTimeModel {
  double fixed_seconds = 0.0;
  double seconds_per_pixel = 0.0;

  double seconds_at(double pixels) const { return fixed_seconds + seconds_per_pixel * pixels; }
};

// The line through the two renders (of different pixel counts), with neither part negative:
// noise that makes the smaller render the slower gives no per-pixel part (every second fixed),
// and a line through zero pixels below zero seconds gives no fixed part. std::invalid_argument
// for renders of equal pixels or of no pixels.
RenderTimeModel fit_render_time(const TimedRender& smaller, const TimedRender& larger);

struct ChosenResolution {
  int width = 0;
  int height = 0;
  double predicted_seconds = 0.0;
  // Within 10% of the target; false when the resolution hit a limit: the fixed part alone is
  // over the target (at min_side), or the target needs more than max_side.
  bool reached = false;
};

// The resolution, of the aspect of `width` x `height`, at which the model predicts
// `target_seconds`; each side in [min_side, max_side]. std::invalid_argument for a target that is
// not a positive number or sides out of order.
ChosenResolution choose_resolution(const RenderTimeModel& model, int width, int height,
                                   double target_seconds, int min_side, int max_side = 16384);

}  // namespace raygate

#include "pipeline/render_time.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace raygate {

RenderTimeModel fit_render_time(const TimedRender& smaller, const TimedRender& larger) {
  if (smaller.pixels() <= 0.0 || larger.pixels() <= 0.0) {
    throw std::invalid_argument("fit_render_time: a render of no pixels");
  }
  if (smaller.pixels() == larger.pixels()) {
    throw std::invalid_argument("fit_render_time: two renders of the same pixel count");
  }
  const TimedRender& a = smaller.pixels() < larger.pixels() ? smaller : larger;
  const TimedRender& b = smaller.pixels() < larger.pixels() ? larger : smaller;
  RenderTimeModel model;
  model.seconds_per_pixel = std::max(0.0, (b.seconds - a.seconds) / (b.pixels() - a.pixels()));
  model.fixed_seconds = b.seconds - model.seconds_per_pixel * b.pixels();
  if (model.fixed_seconds < 0.0) {  // through the origin, by the larger render
    model.fixed_seconds = 0.0;
    model.seconds_per_pixel = b.seconds / b.pixels();
  }
  return model;
}

namespace {

// Sides of the aspect width:height scaled by `scale`, each within the limits.
std::pair<int, int> scaled_sides(int width, int height, double scale, int min_side, int max_side) {
  auto side = [&](int s) {
    const double scaled = std::round(static_cast<double>(s) * scale);
    return static_cast<int>(
        std::clamp(scaled, static_cast<double>(min_side), static_cast<double>(max_side)));
  };
  return {side(width), side(height)};
}

}  // namespace

ChosenResolution choose_resolution(const RenderTimeModel& model, int width, int height,
                                   double target_seconds, int min_side, int max_side) {
  if (!(target_seconds > 0.0) || !std::isfinite(target_seconds)) {
    throw std::invalid_argument("choose_resolution: the target must be a positive number");
  }
  if (width < 1 || height < 1 || min_side < 1 || min_side > max_side) {
    throw std::invalid_argument("choose_resolution: sides out of order");
  }
  const double pixels = static_cast<double>(width) * static_cast<double>(height);
  double scale = 0.0;  // the smallest picture, when no pixels are left for the target
  if (model.seconds_per_pixel > 0.0 && target_seconds > model.fixed_seconds) {
    scale = std::sqrt((target_seconds - model.fixed_seconds) / model.seconds_per_pixel / pixels);
  } else if (model.seconds_per_pixel <= 0.0 && target_seconds > model.fixed_seconds) {
    scale = 1.0;  // no pixel costs anything measurable: keep the suite's own
  }
  const auto [w, h] = scaled_sides(width, height, scale, min_side, max_side);
  ChosenResolution chosen{w, h, model.seconds_at(static_cast<double>(w) * h), false};
  chosen.reached = std::abs(chosen.predicted_seconds - target_seconds) <= 0.1 * target_seconds;
  return chosen;
}

}  // namespace raygate

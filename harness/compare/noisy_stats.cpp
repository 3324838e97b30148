#include "compare/noisy_stats.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace raygate {

namespace {

// Below this many degrees of freedom a scale's own inflation estimate is too rough to use (a
// whole image has one tile: runs - 1 per channel); it takes the next finer scale's instead.
constexpr double kMinInflationDof = 20;

std::size_t pixel_index(int width, int x, int y, int channel) {
  return (static_cast<std::size_t>(y) * width + x) * 3 + channel;
}

// The tile's channel mean of one image.
double tile_mean(const RgbImage& image, const TileRect& t, int channel) {
  double sum = 0;
  for (int y = t.y; y < t.y + t.height; ++y) {
    for (int x = t.x; x < t.x + t.width; ++x) sum += image.at(x, y, channel);
  }
  return sum / (static_cast<double>(t.width) * t.height);
}

// Sum over the tile's pixels of one channel's variance, / pixels²: a tile mean's variance for
// one run if the pixels' noise were independent.
double independent_tile_variance(const std::vector<float>& variance, int width, const TileRect& t,
                                 int channel) {
  double sum = 0;
  for (int y = t.y; y < t.y + t.height; ++y) {
    for (int x = t.x; x < t.x + t.width; ++x) sum += variance[pixel_index(width, x, y, channel)];
  }
  const double pixels = static_cast<double>(t.width) * t.height;
  return sum / (pixels * pixels);
}

}  // namespace

double NoisyImageStats::inflation_for(int tile_px) const {
  for (const ScaleInflation& s : inflation) {
    if (s.tile_px == tile_px) return s.factor;
  }
  return 1.0;
}

std::vector<int> tile_scales(int width, int height, const std::vector<int>& sides) {
  std::vector<int> scales;
  for (const int side : sides) {
    if (side > 0 && side < std::max(width, height)) scales.push_back(side);
  }
  std::sort(scales.begin(), scales.end());
  scales.erase(std::unique(scales.begin(), scales.end()), scales.end());
  scales.push_back(kWholeImage);
  return scales;
}

std::vector<TileRect> tile_grid(int width, int height, int tile_px) {
  if (tile_px == kWholeImage) return {{0, 0, width, height}};
  std::vector<TileRect> tiles;
  for (int y = 0; y < height; y += tile_px) {
    for (int x = 0; x < width; x += tile_px) {
      tiles.push_back({x, y, std::min(tile_px, width - x), std::min(tile_px, height - y)});
    }
  }
  return tiles;
}

void NoisyStatsBuilder::Running::add(std::size_t i, double value, std::size_t n) {
  const double delta = value - mean[i];
  mean[i] += delta / static_cast<double>(n);
  m2[i] += delta * (value - mean[i]);
}

NoisyStatsBuilder::NoisyStatsBuilder(int width, int height, std::vector<int> tile_sides)
    : width_(width), height_(height), scales_(tile_scales(width, height, tile_sides)) {
  const std::size_t values = static_cast<std::size_t>(width) * height * 3;
  pixels_ = {std::vector<double>(values), std::vector<double>(values)};
  for (const int scale : scales_) {
    const std::size_t n = tile_grid(width, height, scale).size() * 3;
    tiles_.push_back({std::vector<double>(n), std::vector<double>(n)});
  }
}

void NoisyStatsBuilder::add(const RgbImage& image) {
  if (image.width != width_ || image.height != height_) {
    throw std::invalid_argument("image is " + std::to_string(image.width) + "x" +
                                std::to_string(image.height) + ", the other runs " +
                                std::to_string(width_) + "x" + std::to_string(height_));
  }
  ++runs_;
  for (std::size_t i = 0; i < image.rgb.size(); ++i) pixels_.add(i, image.rgb[i], runs_);
  for (std::size_t s = 0; s < scales_.size(); ++s) {
    const std::vector<TileRect> grid = tile_grid(width_, height_, scales_[s]);
    for (std::size_t t = 0; t < grid.size(); ++t) {
      for (int c = 0; c < 3; ++c) tiles_[s].add(t * 3 + c, tile_mean(image, grid[t], c), runs_);
    }
  }
}

NoisyImageStats NoisyStatsBuilder::finish() const {
  NoisyImageStats stats;
  stats.width = width_;
  stats.height = height_;
  stats.runs = static_cast<int>(runs_);
  stats.mean.assign(pixels_.mean.begin(), pixels_.mean.end());
  stats.variance.resize(pixels_.m2.size());
  const double dof = runs_ > 1 ? static_cast<double>(runs_ - 1) : 0.0;
  for (std::size_t i = 0; i < pixels_.m2.size(); ++i) {
    stats.variance[i] = dof > 0 ? static_cast<float>(pixels_.m2[i] / dof) : 0.0f;
  }
  double inherited = 1.0;
  for (std::size_t s = 0; s < scales_.size(); ++s) {
    const std::vector<TileRect> grid = tile_grid(width_, height_, scales_[s]);
    double observed = 0, predicted = 0;
    for (std::size_t t = 0; t < grid.size(); ++t) {
      for (int c = 0; c < 3; ++c) {
        observed += dof > 0 ? tiles_[s].m2[t * 3 + c] / dof : 0.0;
        predicted += independent_tile_variance(stats.variance, width_, grid[t], c);
      }
    }
    const double scale_dof = dof * static_cast<double>(grid.size()) * 3;
    if (scale_dof >= kMinInflationDof && predicted > 0) {
      inherited = std::max(1.0, observed / predicted);
    }
    stats.inflation.push_back({scales_[s], inherited});
  }
  return stats;
}

TileEstimate estimate_tile(const NoisyImageStats& stats, const TileRect& tile, int channel,
                           int tile_px) {
  double sum = 0;
  for (int y = tile.y; y < tile.y + tile.height; ++y) {
    for (int x = tile.x; x < tile.x + tile.width; ++x) {
      sum += stats.mean[pixel_index(stats.width, x, y, channel)];
    }
  }
  TileEstimate e;
  e.mean = sum / (static_cast<double>(tile.width) * tile.height);
  if (stats.runs > 0) {
    e.variance_of_mean = stats.inflation_for(tile_px) *
                         independent_tile_variance(stats.variance, stats.width, tile, channel) /
                         stats.runs;
  }
  return e;
}

}  // namespace raygate

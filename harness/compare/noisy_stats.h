// What a set of renders of one scene with independent seeds says about the image a Monte Carlo
// tracer converges to (docs/monte-carlo-images.md): per pixel and channel the mean over the runs
// and the variance of one run's value, and per tile scale how much more a tile's mean varies from
// run to run than its pixels' variances predict (1 when the pixels' noise is independent; more
// for a sampler that correlates neighbouring pixels). Pure arithmetic on float RGB, no files:
// the images come from noisy_image_files.h, the test from noisy_image_compare.h.
#pragma once

#include <cstddef>
#include <vector>

namespace raygate {

// One linear RGB image in memory: width * height * 3 floats, top row first.
struct RgbImage {
  int width = 0, height = 0;
  std::vector<float> rgb;

  float at(int x, int y, int channel) const {
    return rgb[(static_cast<std::size_t>(y) * width + x) * 3 + channel];
  }
};

// A square tile's side in pixels; kWholeImage stands for one tile that is the whole image.
inline constexpr int kWholeImage = 0;

// How much a tile mean's run-to-run variance exceeds the sum of its pixels' variances / pixels².
struct ScaleInflation {
  int tile_px = kWholeImage;
  double factor = 1.0;  // >= 1: never trusts the pixels to be less noisy than they are
  bool operator==(const ScaleInflation&) const = default;
};

// Everything the comparison needs from one side (a revision's runs, or a golden).
struct NoisyImageStats {
  int width = 0, height = 0;
  int runs = 0;  // independent renders summarised; a converged reference is stored with its own
  std::vector<float> mean;      // width * height * 3: per pixel and channel, over the runs
  std::vector<float> variance;  // the same: the sample variance of one run's value (n - 1)
  std::vector<ScaleInflation> inflation;

  // The factor for tiles of `tile_px` (1 when none was measured).
  double inflation_for(int tile_px) const;
};

// Tile sides tried, finest first; kWholeImage last. Sides not smaller than the image are skipped.
std::vector<int> tile_scales(int width, int height, const std::vector<int>& sides);

// Per pixel (Welford's running mean and squared deviations) and per tile of every scale (the
// same over the tile means), so the inflation is measured from the runs themselves.
class NoisyStatsBuilder {
 public:
  NoisyStatsBuilder(int width, int height, std::vector<int> tile_sides);

  // Throws std::invalid_argument when the image's size differs from the first one's.
  void add(const RgbImage& image);
  std::size_t runs() const { return runs_; }
  NoisyImageStats finish() const;

 private:
  struct Running {
    std::vector<double> mean, m2;
    void add(std::size_t i, double value, std::size_t n);
  };
  int width_, height_;
  std::vector<int> scales_;
  std::size_t runs_ = 0;
  Running pixels_;
  std::vector<Running> tiles_;  // per scale: per tile and channel
};

// A tile of the grid of side `tile_px` (the last row and column may be smaller).
struct TileRect {
  int x = 0, y = 0, width = 0, height = 0;
  bool operator==(const TileRect&) const = default;
};

std::vector<TileRect> tile_grid(int width, int height, int tile_px);

// One tile's channel over one side: the mean, and the variance of that mean as an estimate of
// the expected value (the pixels' variances summed, / pixels², / runs, times the inflation).
struct TileEstimate {
  double mean = 0.0;
  double variance_of_mean = 0.0;
};

TileEstimate estimate_tile(const NoisyImageStats& stats, const TileRect& tile, int channel,
                           int tile_px);

}  // namespace raygate

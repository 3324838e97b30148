// The image verdict for Monte Carlo tracers (docs/monte-carlo-images.md): do two sets of renders
// with independent seeds (or renders and a golden's statistics) converge to the same image? Per
// tile at several scales and per RGB channel, a two-sample z test of the tile means (their
// variances from the runs, noisy_stats.h), a weighted Holm step-down over every test of the
// image (each scale gets an equal share of `alpha`, split over its tiles, so the one whole-image
// test is not drowned by hundreds of small tiles) so the chance of any false alarm stays within
// `alpha`, and a minimum effect per scale so a tiny bias
// found with many samples is not a failure. Verdicts: pass (same within noise), fail (biased:
// the tile, by how much, with its interval), inconclusive (too noisy: about how many times the
// samples would decide it).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compare/noisy_stats.h"

namespace raygate {

enum class NoisyVerdict { pass, fail, inconclusive };
std::string_view to_string(NoisyVerdict verdict);

// One tile scale: its side, the smallest relative change that may fail it, and the change it
// must be able to see for a pass.
struct TileScale {
  int tile_px = kWholeImage;
  double min_effect = 0.01;  // relative to the reference tile's mean (or the dark floor)
  // A pass needs this scale's median tile to find a change this large (relative) with
  // probability `power`; else the verdict is inconclusive. 0: no such demand.
  double must_resolve = 0.0;
};

struct NoisyThresholds {
  // Family-wise error rate of one image: the chance that an image whose expected value did not
  // change fails anyway. Callers split a suite's rate over its scenes (Bonferroni).
  double alpha = 0.01;
  std::vector<TileScale> scales{{8, 0.05, 0.0}, {32, 0.03, 0.0}, {128, 0.02, 0.0},
                                {kWholeImage, 0.01, 0.03}};
  // Relative changes are taken against max(tile mean, dark_floor * the image's mean): a tile of
  // near-black pixels must not turn noise-sized absolute differences into huge percentages.
  double dark_floor = 0.1;
  double power = 0.8;  // see TileScale::must_resolve
  int min_runs = 2;    // a side needs this many runs to estimate its own noise
};

struct BiasedTile {
  int tile_px = kWholeImage;
  TileRect rect;
  int channel = 0;  // 0 R, 1 G, 2 B
  double relative_change = 0.0;  // (actual - expected) / reference
  double low = 0.0, high = 0.0;  // its 95% interval
  double z = 0.0;
  double p_value = 1.0;
};

struct ScaleReport {
  int tile_px = kWholeImage;
  std::size_t tiles = 0;
  double min_effect = 0.0;
  // The relative change a median tile of this scale would find with probability `power` at
  // its Bonferroni share of alpha: what this comparison can see here.
  double detectable = 0.0;
  double must_resolve = 0.0;
};

struct NoisyComparison {
  NoisyVerdict verdict = NoisyVerdict::inconclusive;
  int width = 0, height = 0;
  int actual_runs = 0, expected_runs = 0;
  std::optional<std::string> size_mismatch;  // "64x64 against 32x32": fails outright
  std::size_t tests = 0;                     // tiles x channels, the Holm family
  std::vector<BiasedTile> biased;            // failing tiles, largest |z| first
  // The whole image's mean (luminance) change and its 95% interval, relative.
  double image_change = 0.0, image_low = 0.0, image_high = 0.0;
  std::vector<ScaleReport> scales;
  // Inconclusive: about this many times the samples (runs x spp) would make every scale see
  // its must_resolve change; 1 otherwise.
  double samples_factor = 1.0;
  std::string why_inconclusive;
};

// Compares the expected images behind `actual` and `expected`.
NoisyComparison compare_noisy(const NoisyImageStats& actual, const NoisyImageStats& expected,
                              const NoisyThresholds& thresholds);

// One line for a report: "pass (same within noise): mean change -0.2% [-0.6%, +0.2%], 12 vs 12
// runs, 207 tests; sees 1% whole image, 3% in 32 px tiles" or "fail (biased): 32 px tile
// (32,0)-(63,31) G -8.1% [-9.9%, -6.3%], ...".
std::string summarize(const NoisyComparison& comparison);

// The two-sided p of a standard normal z, exposed for tests (the quantile is
// measure/probability.h normal_quantile).
double two_sided_p(double z);

}  // namespace raygate

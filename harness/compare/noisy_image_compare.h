// The image verdict for Monte Carlo tracers (docs/monte-carlo-images.md): do two sets of renders
// with independent seeds (or renders and a golden's statistics) converge to the same image, to
// within one threshold a user reads and sets, the image tolerance?
//
// - pass: the whole image's change is shown to lie within ±tolerance: an equivalence test (two
//   one-sided tests) per RGB channel at `equivalence_alpha` each side, i.e. every channel's
//   (1 - 2 equivalence_alpha) interval, and the luminance mean's, inside ±tolerance; and no tile
//   is biased. No image passes while its interval reaches beyond the tolerance.
// - fail: the whole image's change is shown beyond ±tolerance, or a tile is shown biased (local
//   bias: a two-sample z test of each tile's mean against zero, at 8, 32 and 128 px, counted
//   only when its change is at least its scale's multiple of the tolerance). Every such test of
//   the image is one family under a weighted Holm step-down at `alpha` (each scale an equal
//   share, the whole image one of them), so an image whose change is within the tolerance fails
//   with probability at most `alpha`.
// - inconclusive: neither shown; with about how many times the samples would decide it.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "compare/noisy_stats.h"

namespace raygate {

enum class NoisyVerdict { pass, fail, inconclusive };
std::string_view to_string(NoisyVerdict verdict);
std::optional<NoisyVerdict> parse_noisy_verdict(std::string_view word);

// The image tolerance's default: a whole-image change of 1% in any channel.
inline constexpr double kDefaultImageTolerance = 0.01;

// One tile scale of the local-bias tests: its side, and the smallest change that may fail one
// of its tiles, as a multiple of the image tolerance (small tiles are noisier and smaller).
struct TileScale {
  int tile_px = 8;
  double tolerance_multiple = 1.0;
};

struct NoisyThresholds {
  // The image tolerance (relative change of the whole image's mean, per channel): within it an
  // image is the same, beyond it it is changed. The one threshold of the check.
  double tolerance = kDefaultImageTolerance;
  // Family-wise rate of a false failure of one image whose change is within the tolerance.
  // Callers split a suite's rate over its scenes (Bonferroni).
  double alpha = 0.01;
  // The chance, each side, that an image changed by the tolerance or more passes; reported
  // intervals are at 1 - 2 equivalence_alpha (90%).
  double equivalence_alpha = 0.05;
  std::vector<TileScale> tiles{{8, 5.0}, {32, 3.0}, {128, 2.0}};
  // Relative changes are taken against max(tile mean, dark_floor * the image's mean): a tile of
  // near-black pixels must not turn noise-sized absolute differences into huge percentages.
  double dark_floor = 0.1;
  double power = 0.8;  // for what each scale resolves (ScaleReport::detectable)
  int min_runs = 2;    // a side needs this many runs to estimate its own noise

  double confidence() const { return 1.0 - 2.0 * equivalence_alpha; }
};

// A relative change and its interval at the comparison's confidence.
struct RelativeChange {
  double change = 0.0, low = 0.0, high = 0.0;
  bool operator==(const RelativeChange&) const = default;
};

struct BiasedTile {
  int tile_px = kWholeImage;
  TileRect rect;
  int channel = 0;          // 0 R, 1 G, 2 B
  RelativeChange change;    // (actual - expected) / reference
  double min_effect = 0.0;  // the smallest change that fails it (its scale's, or the tolerance)
  double z = 0.0;           // the test's statistic (whole image: against the tolerance)
  double p_value = 1.0;
  bool operator==(const BiasedTile&) const = default;
};

struct ScaleReport {
  int tile_px = kWholeImage;
  std::size_t tiles = 0;
  // The relative change a median tile of this scale would find with probability `power` at
  // its share of alpha: what this comparison can see here.
  double detectable = 0.0;
  bool operator==(const ScaleReport&) const = default;
};

// The typed result of one comparison: what reports and the results document show.
struct NoisyComparison {
  NoisyVerdict verdict = NoisyVerdict::inconclusive;
  double tolerance = kDefaultImageTolerance;
  double confidence = 0.9;  // of every interval below
  int width = 0, height = 0;
  int actual_runs = 0, expected_runs = 0;
  std::optional<std::string> size_mismatch;  // "64x64 against 32x32": fails outright
  std::size_t tests = 0;                     // tiles x channels, the Holm family
  std::size_t biased_count = 0;              // tests that failed
  std::vector<BiasedTile> biased;            // the worst of them (at most kBiasedKept), |z| first
  RelativeChange image;                      // the whole image's mean (luminance)
  std::array<RelativeChange, 3> channels{};  // the whole image per channel
  std::vector<ScaleReport> scales;
  // Inconclusive: about this many times the samples (runs x spp, both sides) would decide it,
  // projected from the estimate (infinite: the estimate sits on the tolerance); 1 otherwise.
  double samples_factor = 1.0;
  int runs_needed = 0;           // a side, for that; 0 when decided
  std::string why_inconclusive;  // too few runs, or which interval reaches past the tolerance

  bool operator==(const NoisyComparison&) const = default;
};

inline constexpr std::size_t kBiasedKept = 10;

// Compares the expected images behind `actual` and `expected`.
NoisyComparison compare_noisy(const NoisyImageStats& actual, const NoisyImageStats& expected,
                              const NoisyThresholds& thresholds);

// One line for every report, e.g. "pass (within the ±1% image tolerance): image mean -0.20%
// [-0.61%, +0.21%] (90%); 12 vs 12 runs; 207 tests, no tile biased, resolves ..." or
// "fail (biased): ..." or "inconclusive (...)".
std::string summarize(const NoisyComparison& comparison);

// The two-sided p of a standard normal z, exposed for tests (the quantile is
// measure/probability.h normal_quantile).
double two_sided_p(double z);

}  // namespace raygate

// pipeline/image_stop: a compare of a Monte Carlo tracer keeps measuring a scene whose image is
// inconclusive, looking at the image at rounds 2, 3, 5, 8, 12, ... only; and by simulation, what
// those repeated looks cost in error rates: an image changed by exactly the tolerance stopped
// at the first decided look passes at most a little more often than the 5% of one look, where
// looking after every round would let it pass about three times as often.
#include "pipeline/image_stop.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>

#include "compare/noisy_image_check.h"
#include "compare/noisy_image_compare.h"

namespace raygate {
namespace {

TEST(ImageStop, TheImageIsLookedAtEachTimeTheRunsGrowByHalf) {
  const std::vector<std::size_t> expected{0, 0, 2, 3, 3, 5, 5, 5, 8, 8, 8, 8, 12};
  for (std::size_t rounds = 0; rounds < expected.size(); ++rounds) {
    EXPECT_EQ(last_image_look(rounds), expected[rounds]) << rounds;
  }
  EXPECT_EQ(last_image_look(41), 41u);
  EXPECT_EQ(last_image_look(61), 41u);
  EXPECT_EQ(last_image_look(62), 62u);
}

TEST(ImageStop, BothMustBeDecidedAndTheSecondIsAskedOnlyOnceTheFirstIs) {
  int asked = 0;
  const SceneVerdict yes = [](const std::vector<Round>&) { return true; };
  const SceneVerdict no = [](const std::vector<Round>&) { return false; };
  const SceneVerdict counted = [&](const std::vector<Round>&) {
    ++asked;
    return true;
  };
  EXPECT_FALSE(both_decided(no, counted)({}));
  EXPECT_EQ(asked, 0);
  EXPECT_TRUE(both_decided(yes, counted)({}));
  EXPECT_EQ(asked, 1);
  EXPECT_FALSE(both_decided(yes, no)({}));
}

// One scene's runs, simulated: per pixel and channel each run a normal draw around the
// picture's value (times `factor` for head), the statistics at n runs the running mean with the
// known per-run variance. 48x48 pixels, relative noise 0.3.
struct SimulatedScene {
  static constexpr int kSide = 48;
  std::array<double, 3> factor{1, 1, 1};
  std::vector<double> head_sum, base_sum, value;

  explicit SimulatedScene(std::array<double, 3> f) : factor(f) {
    for (int i = 0; i < kSide * kSide; ++i) {
      for (const double v : {0.6, 0.45, 0.3}) value.push_back(v * (1 + 0.5 * (i % 7) / 7.0));
    }
    head_sum.assign(value.size(), 0.0);
    base_sum.assign(value.size(), 0.0);
  }
  void add_run(std::mt19937_64& rng) {
    std::normal_distribution<double> normal(0.0, 0.3);
    for (std::size_t i = 0; i < value.size(); ++i) {
      head_sum[i] += value[i] * factor[i % 3] * (1 + normal(rng));
      base_sum[i] += value[i] * (1 + normal(rng));
    }
  }
  NoisyImageStats stats(const std::vector<double>& sum, const std::array<double, 3>& scale,
                        int runs) const {
    NoisyImageStats s{kSide, kSide, runs, {}, {}, {}};
    for (std::size_t i = 0; i < sum.size(); ++i) {
      s.mean.push_back(static_cast<float>(sum[i] / runs));
      const double sd = 0.3 * value[i] * scale[i % 3];
      s.variance.push_back(static_cast<float>(sd * sd));
    }
    return s;
  }
  NoisyVerdict judge(int runs) const {
    return compare_noisy(stats(head_sum, factor, runs), stats(base_sum, {1, 1, 1}, runs),
                         noisy_thresholds_for(6))
        .verdict;
  }
};

// Per trial: runs added one at a time up to `max_runs`, the image judged at each look (every
// round, or last_image_look's), stopped at the first decided verdict.
std::array<int, 3> sequential(std::array<double, 3> factor, bool every_round, int trials,
                              std::mt19937_64& rng) {
  constexpr int kMaxRuns = 41;
  std::array<int, 3> counts{};  // pass, fail, still inconclusive
  for (int trial = 0; trial < trials; ++trial) {
    SimulatedScene scene(factor);
    NoisyVerdict verdict = NoisyVerdict::inconclusive;
    for (int runs = 1; runs <= kMaxRuns && verdict == NoisyVerdict::inconclusive; ++runs) {
      scene.add_run(rng);
      const bool look = every_round ? runs >= 2 : last_image_look(runs) == std::size_t(runs);
      if (look) verdict = scene.judge(runs);
    }
    ++counts[static_cast<std::size_t>(verdict)];
  }
  return counts;
}

TEST(ImageStop, RepeatedLooksKeepTheErrorRatesNearTheirLevels) {
  std::mt19937_64 rng(73);
  constexpr int kTrials = 200;
  const auto same = sequential({1, 1, 1}, false, kTrials, rng);
  const auto edge = sequential({1.01, 1, 1}, false, kTrials, rng);
  const auto edge_every = sequential({1.01, 1, 1}, true, kTrials, rng);
  const auto changed = sequential({0.97, 0.97, 0.97}, false, kTrials, rng);
  std::printf(
      "up to 41 runs a side, stopped at the first decided look, %d trials each:\n"
      "  unchanged: pass %d fail %d undecided %d\n"
      "  R +1%% (the tolerance), looks at 2,3,5,8,...: pass %d fail %d undecided %d\n"
      "  R +1%%, a look after every run: pass %d fail %d undecided %d\n"
      "  -3%%: pass %d fail %d undecided %d\n",
      kTrials, same[0], same[1], same[2], edge[0], edge[1], edge[2], edge_every[0], edge_every[1],
      edge_every[2], changed[0], changed[1], changed[2]);
  EXPECT_LE(same[1], 5);  // a false failure: alpha 1% split over 6 images, at 8 looks
  EXPECT_GE(same[0], kTrials * 9 / 10);
  // 5% of one look is 10. Repeated looks raise it: 26 of 200 (13%) when written, against 42 with
  // a look after every run (docs/monte-carlo-images.md, "Looking again"). 38 is the 99.9% bound
  // at 13%: a schedule that peeks more than today's fails here.
  EXPECT_LE(edge[0], 38);
  EXPECT_LE(edge[0], edge_every[0]);
  EXPECT_GE(changed[1], kTrials * 95 / 100);
  EXPECT_EQ(changed[0], 0);
}

}  // namespace
}  // namespace raygate

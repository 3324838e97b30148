// The normalized ratio time(tracer) / time(baseline) of one scene, from interleaved rounds, and
// the suite score over scenes (DESIGN.md §6). Each round is a pair measured back to back on the
// same machine, so the round's log-ratio cancels whatever that machine was doing at the time;
// the median over rounds ignores the odd round that a neighbour's job disturbed.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "measure/bootstrap.h"

namespace raygate {

struct RoundSample {
  double tracer_seconds = 0.0;
  double baseline_seconds = 0.0;
};

struct RatioSummary {
  std::size_t rounds = 0;
  double ratio = 0.0;                // exp(median of per-round ln(tracer / baseline))
  Interval ratio_interval;           // order statistics of the rounds' log-ratios, in ratio units
  double relative_half_width = 0.0;  // ratio_interval.width() / 2 / ratio: the stopping rule's
  double log_ratio_median = 0.0;
  double log_ratio_mad_scaled = 0.0;  // scaled MAD of the log-ratios: about the relative spread
  double tracer_median_seconds = 0.0;
  double baseline_median_seconds = 0.0;  // for machine-drift checks against history
};

// ln(tracer_seconds / baseline_seconds) per round, in round order. Throws InfraError naming the
// round if a time is not positive and finite (a tracer that reports 0 s cannot be normalized).
std::vector<double> log_ratios(std::span<const RoundSample> rounds);

// The interval is the distribution-free order-statistic interval of the median log-ratio at
// `confidence` (measure/median_interval.h), or the rounds' range below the rounds that needs.
// Throws std::invalid_argument for no rounds, InfraError for bad times (see log_ratios).
RatioSummary summarize_ratio(std::span<const RoundSample> rounds, double confidence = 0.95);

struct SuiteScore {
  std::size_t scenes = 0;
  double score = 0.0;  // geometric mean of the scenes' normalized ratios
  Interval interval;   // bootstrap: rounds resampled within each scene, independently
};

// One entry of `scenes` per scene, each that scene's rounds. Scenes are measured separately, so
// each replicate resamples every scene's rounds independently (one generator, scenes in order)
// and takes exp(mean over scenes of the replicate's median log-ratio).
SuiteScore suite_score(std::span<const std::vector<RoundSample>> scenes,
                       const BootstrapOptions& options = {});

}  // namespace raygate

#include "pipeline/stored_ratio.h"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/format.h"
#include "measure/median_interval.h"
#include "measure/probability.h"
#include "pipeline/stop_rules.h"

namespace raygate {

double stored_ratio_confidence(const GatePolicy& policy, const std::string& scene_id) {
  return change_bootstrap(policy.for_scene(scene_id)).confidence;
}

std::size_t stored_ratio_fewest_rounds(double confidence) {
  return min_values_for_median_interval(confidence);
}

bool stored_ratio_precise(const RatioSummary& ratio, double confidence) {
  return ratio.rounds >= stored_ratio_fewest_rounds(confidence) &&
         ratio.relative_half_width <= kStoredRatioHalfWidth;
}

std::size_t stored_ratio_rounds_needed(const RatioSummary& ratio, double confidence) {
  const double z = normal_quantile(0.5 + confidence / 2.0);
  const double root = z * 1.2533 * ratio.log_ratio_mad_scaled / kStoredRatioHalfWidth;
  const double rounds = std::ceil(root * root);
  const double fewest = static_cast<double>(stored_ratio_fewest_rounds(confidence));
  // Capped well above any round limit, so a wild spread cannot overflow the count.
  return static_cast<std::size_t>(std::clamp(rounds, fewest, 1e6));
}

std::size_t stored_ratio_rounds_left(const SceneResult& scene) {
  const std::size_t joined = round_samples(scene.runs.rounds, Role::base).size();
  return joined >= kStoredRatioMaxRounds ? 0 : kStoredRatioMaxRounds - joined;
}

StopRule stored_ratio_stop_rule(const StoppingPolicy& policy, double confidence) {
  return stop_rule(policy, [confidence](const std::vector<Round>& rounds) {
    const std::vector<RoundSample> samples = round_samples(rounds, Role::base);
    return !samples.empty() &&
           stored_ratio_precise(summarize_ratio(samples, confidence), confidence);
  });
}

namespace {

// "balls 0.412 [0.398, 0.431] (+-4.0%) from 6 baseline rounds (why)"; from one round, which has
// no spread, "balls 0.412 from 1 baseline round, no interval (why)", not "[0.412, 0.412] (+-0.0%)".
std::string imprecise_text(const SceneResult& scene, const RatioSummary& ratio,
                           const std::map<std::string, std::string>& why_by_scene) {
  const auto why = why_by_scene.find(scene.entry.id);
  const std::string interval =
      ratio.rounds < 2 ? ""
                       : fmt::format(" [{:.3f}, {:.3f}] (+-{:.1f}%)", ratio.ratio_interval.lower,
                                     ratio.ratio_interval.upper, 100.0 * ratio.relative_half_width);
  return fmt::format("{} {:.3f}{} from {}{} ({})", scene.entry.id, ratio.ratio, interval,
                     count_text(ratio.rounds, "baseline round"),
                     ratio.rounds < 2 ? ", no interval" : "",
                     why == why_by_scene.end() ? "no ratio rounds" : why->second);
}

}  // namespace

std::string stored_ratio_line(const ResultsDocument& document, const GatePolicy& policy,
                              const std::map<std::string, std::string>& why_by_scene) {
  // Counted costs (--timing sim) repeat, so two rounds' range bounds the ratio: it is not a
  // sample's interval, and the fewest rounds a median interval needs do not apply.
  const bool counted = document.settings.timing_source == TimingSource::simulated;
  const auto precise = [&](const RatioSummary& ratio, const std::string& scene_id) {
    if (counted) return ratio.rounds >= 2 && ratio.relative_half_width <= kStoredRatioHalfWidth;
    return stored_ratio_precise(ratio, stored_ratio_confidence(policy, scene_id));
  };
  std::size_t measured = 0;
  std::size_t fewest = 0;
  std::size_t most = 0;
  std::vector<std::string> imprecise;
  for (const SceneResult& scene : document.scenes) {
    const RatioSummary* ratio = scene.ratio(Role::base);
    if (ratio == nullptr || ratio->rounds == 0) continue;
    fewest = measured == 0 ? ratio->rounds : std::min(fewest, ratio->rounds);
    most = std::max(most, ratio->rounds);
    ++measured;
    if (!precise(*ratio, scene.entry.id)) {
      imprecise.push_back(imprecise_text(scene, *ratio, why_by_scene));
    }
  }
  if (measured == 0) return "";
  std::string line = fmt::format(
      "stored ratios (base against the baseline, what history trends): CI within +-{:.0f}% on {} "
      "of {}, from {}",
      100.0 * kStoredRatioHalfWidth, measured - imprecise.size(), count_text(measured, "scene"),
      fewest == most ? count_text(most, "baseline round")
                     : fmt::format("{}-{} baseline rounds", fewest, most));
  if (counted) line += " (counted in simulated cycles: the range of their counts)";
  for (std::size_t i = 0; i < imprecise.size(); ++i) {
    line += (i == 0 ? "; not: " : "; ") + imprecise[i];
  }
  return line;
}

}  // namespace raygate

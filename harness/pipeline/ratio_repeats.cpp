#include "pipeline/ratio_repeats.h"

#include <optional>

#include "measure/fastest_of_two.h"
#include "measure/ratio.h"

namespace raygate {

std::size_t ratio_repeats(const std::vector<Round>& rounds_so_far, Role tracer_role,
                          Role baseline_role) {
  std::vector<Round> one_run;
  std::vector<Round> repeated;
  for (const Round& round : rounds_so_far) {
    (runs_per_contender(round) >= 2 ? repeated : one_run).push_back(round);
  }
  const std::vector<RoundSample> one_run_samples =
      round_samples(one_run, tracer_role, baseline_role);
  if (one_run_samples.size() < 2 * kMinPairsForSpread) return 1;
  const std::vector<RoundSample> repeated_samples =
      round_samples(repeated, tracer_role, baseline_role);
  const std::optional<double> repeated_spread =
      repeated_samples.size() >= 2 * kMinPairsForSpread
          ? std::optional<double>(quartile_spread(log_ratios(repeated_samples)))
          : fastest_of_two_spread(one_run_samples);
  if (!repeated_spread) return 1;
  const double one_run_spread = quartile_spread(log_ratios(one_run_samples));
  return fastest_of_two_pays(one_run_spread, *repeated_spread) ? 2 : 1;
}

}  // namespace raygate

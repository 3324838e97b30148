#include "report/ratio_interval_text.h"

#include <fmt/core.h>

namespace raygate {

std::string ratio_interval_text(const RatioSummary& ratio) {
  if (ratio.rounds < 2) {
    return fmt::format("{:.3f} ({} round: no interval)", ratio.ratio, ratio.rounds);
  }
  return fmt::format("{:.3f} [{:.3f}, {:.3f}]", ratio.ratio, ratio.ratio_interval.lower,
                     ratio.ratio_interval.upper);
}

}  // namespace raygate

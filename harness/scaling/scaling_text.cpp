// Wording of the growth fits: every number a reader needs to judge the fit, and the diagnosis
// in words rather than a code.
#include "scaling/scaling_text.h"

#include <fmt/core.h>

#include "scaling/fit_limits.h"

namespace raygate {
namespace {

std::string quality_words(const PowerFit& fit) {
  switch (fit.quality) {
    case FitQuality::power_law:
      return fmt::format("power law fits (the points within ±{:.0f}% of the line)",
                         100.0 * kScatterLimit);
    case FitQuality::startup_dominated:
      return fmt::format(
          "power law does not fit: a fixed cost of {:.3g} s dominates the small "
          "sizes (local k {:.2f} -> {:.2f}); beyond it t grows as n^{:.2f}",
          fit.fixed_cost, fit.small_end_exponent, fit.large_end_exponent, fit.growth_exponent);
    case FitQuality::curved:
      return fmt::format(
          "power law does not fit: the local exponent moves from {:.2f} to {:.2f} "
          "along the range",
          fit.small_end_exponent, fit.large_end_exponent);
    case FitQuality::scattered:
      return fmt::format(
          "power law does not fit: the points scatter around the line by more than ±{:.0f}%",
          100.0 * kScatterLimit);
    case FitQuality::too_few_points: return "too few sizes for an interval";
  }
  return "";
}

std::string projection_words(const std::string& family, const Projection& p) {
  return fmt::format("at {} size {} ({} primitives) head is projected {:+.0f}% {}", family, p.size,
                     p.primitives, 100 * p.change, p.change >= 0 ? "slower" : "faster");
}

}  // namespace

std::string describe_fit(const PowerFit& fit) {
  if (fit.points < 3)
    return fmt::format("k {:.2f} from {} sizes, {}", fit.exponent, fit.points, quality_words(fit));
  return fmt::format("k {:.2f} [{:.2f}, {:.2f}], r² {:.3f}, {}", fit.exponent,
                     fit.exponent_interval.lower, fit.exponent_interval.upper, fit.r_squared,
                     quality_words(fit));
}

std::string describe_change(const std::string& family, const ExponentChange& change) {
  const PowerFit& fit = change.judged();
  std::string text = fmt::format(
      "exponent head - base {:+.2f} [{:+.2f}, {:+.2f}]{} (limit {:+.2f}): {}", fit.exponent,
      fit.exponent_interval.lower, fit.exponent_interval.upper,
      change.large_end
          ? fmt::format(" between the two largest sizes (over all {}: {:+.2f}, "
                        "{})",
                        change.fit.points, change.fit.exponent, to_string(change.fit.quality))
          : "",
      change.limit, to_string(change.verdict));
  if (change.crossing) {
    text += fmt::format("; {} (speed limit {:.0f}%)", projection_words(family, *change.crossing),
                        100 * change.slowdown);
  } else if (change.largest) {
    text += fmt::format("; head stays within the speed limit ({:.0f}%) up to the largest size",
                        100 * change.slowdown);
  }
  if (change.largest && (!change.crossing || change.crossing->size != change.largest->size)) {
    text += "; " + projection_words(family, *change.largest);
  }
  return text;
}

std::vector<std::string> scaling_lines(const ScalingAnalysis& analysis) {
  std::vector<std::string> lines;
  for (const FamilyScaling& f : analysis.families) {
    lines.push_back(fmt::format("scaling {}: {} sizes, {}..{} primitives", f.family,
                                f.points.size(), f.points.front().primitives,
                                f.points.back().primitives));
    lines.push_back(fmt::format("  {:<16} {}", "baseline", describe_fit(f.baseline)));
    for (const auto& [role, fits] : f.roles) {
      lines.push_back(fmt::format("  {:<16} {}", to_string(role), describe_fit(fits.time)));
      lines.push_back(
          fmt::format("  {:<16} {}", role_name(role) + " ratio", describe_fit(fits.ratio)));
    }
    if (f.change) lines.push_back("  " + describe_change(f.family, *f.change));
  }
  return lines;
}

}  // namespace raygate

// Grouping a document's scenes into families and fitting each; the compare judgement and its
// projection to larger SPD sizes.
#include "scaling/scaling_analysis.h"

#include <algorithm>
#include <cmath>

#include "spd.h"
#include "results/series.h"

namespace raygate {
namespace {

constexpr int kMinimumSizes = 3;

int resolved_size(const SuiteScene& entry) {
  if (entry.size > 0) return entry.size;
  const scenes::SceneGenerator* generator = scenes::find_generator(entry.scene);
  return generator ? generator->default_size : 0;
}

ScalingPoint point_of(const SceneResult& scene, const PrimitiveCounter& count) {
  ScalingPoint point;
  point.scene_id = scene.entry.id;
  point.size = resolved_size(scene.entry);
  point.primitives = count(scene.entry.scene, point.size);
  for (const auto& [role, ratio] : scene.ratios) {
    point.baseline_seconds = ratio.baseline_median_seconds;
    point.seconds[role] = ratio.tracer_median_seconds;
    point.ratios[role] = ratio.ratio;
  }
  if (scene.change) {
    point.change = scene.change->change;
    point.change_interval = scene.change->change_interval;
  }
  return point;
}

PowerFit fit_points(const std::vector<ScalingPoint>& points,
                    const std::function<double(const ScalingPoint&)>& value) {
  std::vector<SizePoint> sizes;
  for (const ScalingPoint& p : points)
    sizes.push_back({static_cast<double>(p.primitives), value(p)});
  return fit_power_law(sizes);
}

std::string family_series(const ResultsDocument& document,
                          const std::vector<const SceneResult*>& scenes) {
  const RevisionRecord* revision = document.revision(primary_role(document.kind));
  std::string settings;
  for (const SceneResult* scene : scenes) {
    settings += (settings.empty() ? "" : "; ") + scene_settings(scene->entry, document.baseline);
  }
  const SeriesKey key{revision ? repository_key(*revision) : "unknown",
                      revision ? revision->adapter_name : "",
                      document.suite,
                      "family:" + scenes.front()->entry.scene,
                      settings,
                      timing_identity(document),
                      baseline_identity(document.baseline),
                      revision ? revision->adapter_measurement : ""};
  return key.id();
}

// Walks the family's SPD sizes upward from the smallest: the first where the projected change
// passes the speed limit, and the largest the generator makes.
void project(ExponentChange& change, const std::string& family, const PrimitiveCounter& count) {
  const scenes::SceneGenerator* generator = scenes::find_generator(family);
  if (!generator || !generator->uses_size) return;
  const int largest = max_size(*generator);
  for (int size = 1; size <= largest; ++size) {
    const std::int64_t n = count(family, size);
    const Projection at{size, n, change.judged().predict(static_cast<double>(n)) - 1.0};
    if (!change.crossing && at.change > change.slowdown) change.crossing = at;
    if (size == largest) change.largest = at;
  }
}

// The slope of ln(head/base) between two sizes, with the interval from their change intervals:
// [ln(1+lo₂) - ln(1+hi₁), ln(1+hi₂) - ln(1+lo₁)] over the step in ln n. nullopt without both
// intervals.
std::optional<PowerFit> local_change(const ScalingPoint& smaller, const ScalingPoint& larger) {
  if (!smaller.change_interval || !larger.change_interval || smaller.change_interval->lower <= -1 ||
      larger.change_interval->lower <= -1) {
    return std::nullopt;
  }
  const double step = std::log(static_cast<double>(larger.primitives)) -
                      std::log(static_cast<double>(smaller.primitives));
  if (!(step > 0)) return std::nullopt;
  PowerFit fit;
  fit.points = 2;
  fit.exponent = (std::log1p(*larger.change) - std::log1p(*smaller.change)) / step;
  fit.exponent_interval = {
      (std::log1p(larger.change_interval->lower) - std::log1p(smaller.change_interval->upper)) /
          step,
      (std::log1p(larger.change_interval->upper) - std::log1p(smaller.change_interval->lower)) /
          step};
  fit.log_prefactor =
      std::log1p(*larger.change) - fit.exponent * std::log(static_cast<double>(larger.primitives));
  fit.r_squared = 1.0;
  fit.quality = FitQuality::power_law;  // two points: a line by construction
  fit.small_end_exponent = fit.large_end_exponent = fit.growth_exponent = fit.exponent;
  return fit;
}

std::optional<ExponentChange> exponent_change(const std::vector<ScalingPoint>& points,
                                              const std::string& family,
                                              const ScalingLimits& limits,
                                              const PrimitiveCounter& count) {
  const bool paired = std::all_of(points.begin(), points.end(), [](const ScalingPoint& p) {
    return p.change.has_value() && *p.change > -1.0;
  });
  if (!paired) return std::nullopt;
  ExponentChange change;
  const auto head_over_base = [](const ScalingPoint& p) { return 1.0 + *p.change; };
  change.fit = fit_points(points, head_over_base);
  // A line that does not describe the points (typically flat, then rising) averages a slope
  // nobody will see: what extrapolates to production sizes is the slope at the large end.
  if (change.fit.quality != FitQuality::power_law && points.size() >= 3) {
    change.large_end = local_change(points[points.size() - 2], points.back());
  }
  change.limit = limits.max_exponent_increase;
  change.slowdown = limits.max_slowdown;
  change.verdict = judge_exponent(change);
  // A change of exponent this small is noise: projecting it to a million primitives would
  // announce a slowdown the measurement does not show.
  if (change.verdict != ChangeVerdict::unchanged) project(change, family, count);
  return change;
}

FamilyScaling analyse_family(const ResultsDocument& document,
                             const std::vector<const SceneResult*>& scenes,
                             const ScalingLimits& limits, const PrimitiveCounter& count) {
  FamilyScaling family;
  family.family = scenes.front()->entry.scene;
  family.series_id = family_series(document, scenes);
  for (const SceneResult* scene : scenes) family.points.push_back(point_of(*scene, count));
  std::sort(
      family.points.begin(), family.points.end(),
      [](const ScalingPoint& a, const ScalingPoint& b) { return a.primitives < b.primitives; });
  family.baseline =
      fit_points(family.points, [](const ScalingPoint& p) { return p.baseline_seconds; });
  for (const auto& entry : family.points.front().seconds) {
    const Role role = entry.first;
    RoleScaling fits;
    fits.time =
        fit_points(family.points, [&](const ScalingPoint& p) { return p.seconds.at(role); });
    fits.ratio =
        fit_points(family.points, [&](const ScalingPoint& p) { return p.ratios.at(role); });
    family.roles[role] = fits;
  }
  family.change = exponent_change(family.points, family.family, limits, count);
  return family;
}

bool usable(const SceneResult& scene, const std::vector<Role>& roles) {
  if (scene.status != SceneStatus::measured || scene.ratios.empty()) return false;
  return std::all_of(roles.begin(), roles.end(), [&](Role role) {
    const RatioSummary* ratio = scene.ratio(role);
    return ratio && ratio->tracer_median_seconds > 0 && ratio->baseline_median_seconds > 0 &&
           ratio->ratio > 0;
  });
}

}  // namespace

ScalingAnalysis analyse_scaling(const ResultsDocument& document, const ScalingLimits& limits,
                                const PrimitiveCounter& count) {
  const std::vector<Role> roles = revision_roles(document.kind);
  std::vector<std::string> order;
  std::map<std::string, std::vector<const SceneResult*>> by_family;
  for (const SceneResult& scene : document.scenes) {
    if (!usable(scene, roles)) continue;
    auto& members = by_family[scene.entry.scene];
    if (members.empty()) order.push_back(scene.entry.scene);
    members.push_back(&scene);
  }
  ScalingAnalysis analysis;
  analysis.max_exponent_increase = limits.max_exponent_increase;
  for (const std::string& family : order) {
    const auto& members = by_family[family];
    std::vector<int> sizes;
    for (const SceneResult* scene : members) sizes.push_back(resolved_size(scene->entry));
    std::sort(sizes.begin(), sizes.end());
    if (std::unique(sizes.begin(), sizes.end()) - sizes.begin() < kMinimumSizes) continue;
    analysis.families.push_back(analyse_family(document, members, limits, count));
  }
  return analysis;
}

ChangeVerdict judge_exponent(const ExponentChange& change) {
  const PowerFit& fit = change.judged();
  if (fit.quality == FitQuality::too_few_points) return ChangeVerdict::inconclusive;
  return classify_change(fit.exponent, fit.exponent_interval, change.limit);
}

std::optional<ChangeVerdict> worst_exponent_verdict(const ScalingAnalysis& analysis) {
  std::optional<ChangeVerdict> worst;
  const auto rank = [](ChangeVerdict v) {
    return v == ChangeVerdict::regressed ? 3 : v == ChangeVerdict::inconclusive ? 2 : 1;
  };
  for (const FamilyScaling& family : analysis.families) {
    if (!family.change) continue;
    if (!worst || rank(family.change->verdict) > rank(*worst)) worst = family.change->verdict;
  }
  return worst;
}

}  // namespace raygate

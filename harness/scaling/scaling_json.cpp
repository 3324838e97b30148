// Field by field, with enums as their strings; optional parts are absent rather than null.
#include "scaling/scaling_json.h"

#include <stdexcept>

#include "core/error.h"

namespace raygate {
namespace {

using json = nlohmann::json;

json fit_json(const PowerFit& f) {
  return json{{"points", f.points},
              {"exponent", f.exponent},
              {"exponent_interval", {f.exponent_interval.lower, f.exponent_interval.upper}},
              {"log_prefactor", f.log_prefactor},
              {"r_squared", f.r_squared},
              {"quality", std::string(to_string(f.quality))},
              {"small_end_exponent", f.small_end_exponent},
              {"large_end_exponent", f.large_end_exponent},
              {"fixed_cost_seconds", f.fixed_cost},
              {"growth_exponent", f.growth_exponent}};
}

PowerFit fit_from(const json& j) {
  PowerFit f;
  f.points = j.at("points").get<int>();
  f.exponent = j.at("exponent").get<double>();
  f.exponent_interval = {j.at("exponent_interval").at(0).get<double>(),
                         j.at("exponent_interval").at(1).get<double>()};
  f.log_prefactor = j.at("log_prefactor").get<double>();
  f.r_squared = j.at("r_squared").get<double>();
  f.quality = fit_quality_from_string(j.at("quality").get<std::string>());
  f.small_end_exponent = j.at("small_end_exponent").get<double>();
  f.large_end_exponent = j.at("large_end_exponent").get<double>();
  f.fixed_cost = j.at("fixed_cost_seconds").get<double>();
  f.growth_exponent = j.at("growth_exponent").get<double>();
  return f;
}

json point_json(const ScalingPoint& p) {
  json j{{"scene", p.scene_id},     {"size", p.size},     {"primitives", p.primitives},
         {"baseline_seconds", p.baseline_seconds}, {"seconds", p.seconds}, {"ratios", p.ratios}};
  if (p.change) j["change"] = *p.change;
  if (p.change_interval) j["change_interval"] = {p.change_interval->lower, p.change_interval->upper};
  return j;
}

ScalingPoint point_from(const json& j) {
  ScalingPoint p;
  p.scene_id = j.at("scene").get<std::string>();
  p.size = j.at("size").get<int>();
  p.primitives = j.at("primitives").get<std::int64_t>();
  p.baseline_seconds = j.at("baseline_seconds").get<double>();
  p.seconds = j.at("seconds").get<std::map<std::string, double>>();
  p.ratios = j.at("ratios").get<std::map<std::string, double>>();
  if (j.contains("change")) p.change = j.at("change").get<double>();
  if (j.contains("change_interval")) {
    p.change_interval = Interval{j.at("change_interval").at(0).get<double>(),
                                 j.at("change_interval").at(1).get<double>()};
  }
  return p;
}

json projection_json(const Projection& p) {
  return json{{"size", p.size}, {"primitives", p.primitives}, {"change", p.change}};
}

Projection projection_from(const json& j) {
  return {j.at("size").get<int>(), j.at("primitives").get<std::int64_t>(),
          j.at("change").get<double>()};
}

ChangeVerdict verdict_from(const std::string& text) {
  for (const ChangeVerdict v : {ChangeVerdict::unchanged, ChangeVerdict::improved,
                                ChangeVerdict::regressed, ChangeVerdict::inconclusive}) {
    if (to_string(v) == text) return v;
  }
  throw std::invalid_argument("unknown verdict '" + text + "'");
}

json change_json(const ExponentChange& c) {
  json j{{"fit", fit_json(c.fit)},
         {"judged", c.large_end ? "large-end" : "all-sizes"},
         {"verdict", std::string(to_string(c.verdict))},
         {"limit", c.limit},
         {"max_slowdown", c.slowdown}};
  if (c.large_end) j["large_end_fit"] = fit_json(*c.large_end);
  if (c.crossing) j["crossing"] = projection_json(*c.crossing);
  if (c.largest) j["largest"] = projection_json(*c.largest);
  return j;
}

ExponentChange change_from(const json& j) {
  ExponentChange c;
  c.fit = fit_from(j.at("fit"));
  if (j.contains("large_end_fit")) c.large_end = fit_from(j.at("large_end_fit"));
  c.verdict = verdict_from(j.at("verdict").get<std::string>());
  c.limit = j.at("limit").get<double>();
  c.slowdown = j.at("max_slowdown").get<double>();
  if (j.contains("crossing")) c.crossing = projection_from(j.at("crossing"));
  if (j.contains("largest")) c.largest = projection_from(j.at("largest"));
  return c;
}

json family_json(const FamilyScaling& f) {
  json points = json::array();
  for (const ScalingPoint& p : f.points) points.push_back(point_json(p));
  json roles = json::object();
  for (const auto& [role, fits] : f.roles) {
    roles[role] = json{{"time", fit_json(fits.time)}, {"ratio", fit_json(fits.ratio)}};
  }
  json j{{"family", f.family},  {"series_id", f.series_id}, {"points", points},
         {"baseline", fit_json(f.baseline)}, {"roles", roles}};
  if (f.change) j["change"] = change_json(*f.change);
  return j;
}

FamilyScaling family_from(const json& j) {
  FamilyScaling f;
  f.family = j.at("family").get<std::string>();
  f.series_id = j.at("series_id").get<std::string>();
  for (const json& p : j.at("points")) f.points.push_back(point_from(p));
  f.baseline = fit_from(j.at("baseline"));
  for (const auto& [role, fits] : j.at("roles").items()) {
    f.roles[role] = RoleScaling{fit_from(fits.at("time")), fit_from(fits.at("ratio"))};
  }
  if (j.contains("change")) f.change = change_from(j.at("change"));
  return f;
}

}  // namespace

nlohmann::json to_json(const ScalingAnalysis& analysis) {
  json families = json::array();
  for (const FamilyScaling& f : analysis.families) families.push_back(family_json(f));
  return json{{"max_exponent_increase", analysis.max_exponent_increase}, {"families", families}};
}

ScalingAnalysis scaling_from_json(const nlohmann::json& j, const std::string& origin) {
  try {
    ScalingAnalysis analysis;
    analysis.max_exponent_increase = j.at("max_exponent_increase").get<double>();
    for (const json& f : j.at("families")) analysis.families.push_back(family_from(f));
    return analysis;
  } catch (const json::exception& e) {
    throw UsageError(origin + ": $.scaling is not a scaling analysis: " + e.what());
  } catch (const std::invalid_argument& e) {
    throw UsageError(origin + ": $.scaling: " + e.what());
  }
}

}  // namespace raygate

// Field by field, with enums as their words; optional parts are absent rather than null. A
// number that was not finite is written null (as nlohmann writes NaN) and read back as NaN.
#include "results/scaling_json.h"

#include <array>
#include <utility>

#include "core/enum_words.h"
#include "results/typed_fields.h"

namespace raygate {
namespace {

using json = nlohmann::json;
using namespace typed_fields;

// Each quality's name in results documents and reports: one table, read both ways.
constexpr EnumWords<FitQuality, 5> kQualityNames{
    {{FitQuality::power_law, "power-law"},
     {FitQuality::startup_dominated, "startup-dominated"},
     {FitQuality::curved, "curved"},
     {FitQuality::scattered, "scattered"},
     {FitQuality::too_few_points, "too-few-points"}}};

// An optional part: read when the key is there (absent rather than null, as written).
template <typename Read>
auto if_present(const JsonField& j, const char* key, Read read)
    -> std::optional<decltype(read(j))> {
  if (!j.has(key)) return std::nullopt;
  return read(j.member(key));
}

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

Interval interval_from(const JsonField& pair) {
  const std::vector<JsonField> bounds = pair.elements();
  if (bounds.size() != 2) pair.fail("expected [lower, upper]");
  return {number_or_nan(bounds[0]), number_or_nan(bounds[1])};
}

FitQuality quality_from(const JsonField& field) {
  const std::string word = field.as_string();
  const std::optional<FitQuality> quality = parse_fit_quality(word);
  if (!quality) {
    field.fail("unknown fit quality \"" + word +
               "\" (power-law, startup-dominated, curved, "
               "scattered or too-few-points)");
  }
  return *quality;
}

PowerFit fit_from(const JsonField& j) {
  PowerFit f;
  f.points = int_of(j.member("points"));
  f.exponent = number_or_nan(j.member("exponent"));
  f.exponent_interval = interval_from(j.member("exponent_interval"));
  f.log_prefactor = number_or_nan(j.member("log_prefactor"));
  f.r_squared = number_or_nan(j.member("r_squared"));
  f.quality = quality_from(j.member("quality"));
  f.small_end_exponent = number_or_nan(j.member("small_end_exponent"));
  f.large_end_exponent = number_or_nan(j.member("large_end_exponent"));
  f.fixed_cost = number_or_nan(j.member("fixed_cost_seconds"));
  f.growth_exponent = number_or_nan(j.member("growth_exponent"));
  return f;
}

json point_json(const ScalingPoint& p) {
  json j{{"scene", p.scene_id},
         {"size", p.size},
         {"primitives", p.primitives},
         {"baseline_seconds", p.baseline_seconds},
         {"seconds", role_object(p.seconds, record_json<double>)},
         {"ratios", role_object(p.ratios, record_json<double>)}};
  if (p.change) j["change"] = *p.change;
  if (p.change_interval)
    j["change_interval"] = {p.change_interval->lower, p.change_interval->upper};
  return j;
}

ScalingPoint point_from(const JsonField& j) {
  ScalingPoint p;
  p.scene_id = j.member("scene").as_string();
  p.size = int_of(j.member("size"));
  p.primitives = whole(j.member("primitives"), 0, std::numeric_limits<std::int64_t>::max());
  p.baseline_seconds = number_or_nan(j.member("baseline_seconds"));
  p.seconds = by_role(j.member("seconds"), number_or_nan);
  p.ratios = by_role(j.member("ratios"), number_or_nan);
  p.change = if_present(j, "change", number_or_nan);
  p.change_interval = if_present(j, "change_interval", interval_from);
  return p;
}

json projection_json(const Projection& p) {
  return json{{"size", p.size}, {"primitives", p.primitives}, {"change", p.change}};
}

Projection projection_from(const JsonField& j) {
  return {int_of(j.member("size")),
          whole(j.member("primitives"), 0, std::numeric_limits<std::int64_t>::max()),
          number_or_nan(j.member("change"))};
}

ChangeVerdict verdict_from(const JsonField& field) {
  const std::string word = field.as_string();
  const std::optional<ChangeVerdict> verdict = change_verdict_named(word);
  if (!verdict) {
    field.fail("unknown verdict \"" + word + "\" (UNCHANGED, IMPROVED, REGRESSED or INCONCLUSIVE)");
  }
  return *verdict;
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

// "judged" is not read: it says which fit judged(), which large_end_fit's presence decides.
ExponentChange change_from(const JsonField& j) {
  return {.fit = fit_from(j.member("fit")),
          .large_end = if_present(j, "large_end_fit", fit_from),
          .verdict = verdict_from(j.member("verdict")),
          .limit = number_or_nan(j.member("limit")),
          .slowdown = number_or_nan(j.member("max_slowdown")),
          .crossing = if_present(j, "crossing", projection_from),
          .largest = if_present(j, "largest", projection_from)};
}

json family_json(const FamilyScaling& f) {
  json points = json::array();
  for (const ScalingPoint& p : f.points) points.push_back(point_json(p));
  const json roles = role_object(f.roles, [](const RoleScaling& fits) {
    return json{{"time", fit_json(fits.time)}, {"ratio", fit_json(fits.ratio)}};
  });
  json j{{"family", f.family},
         {"series_id", f.series_id},
         {"points", points},
         {"baseline", fit_json(f.baseline)},
         {"roles", roles}};
  if (f.change) j["change"] = change_json(*f.change);
  return j;
}

FamilyScaling family_from(const JsonField& j) {
  FamilyScaling f;
  f.family = j.member("family").as_string();
  f.series_id = j.member("series_id").as_string();
  for (const JsonField& p : j.member("points").elements()) f.points.push_back(point_from(p));
  f.baseline = fit_from(j.member("baseline"));
  f.roles = by_role(j.member("roles"), [](const JsonField& fits) {
    return RoleScaling{fit_from(fits.member("time")), fit_from(fits.member("ratio"))};
  });
  f.change = if_present(j, "change", change_from);
  return f;
}

}  // namespace

std::string_view to_string(FitQuality quality) { return word_of(kQualityNames, quality, "?"); }

std::optional<FitQuality> parse_fit_quality(std::string_view text) {
  return value_of(kQualityNames, text);
}

nlohmann::json to_json(const ScalingAnalysis& analysis) {
  json families = json::array();
  for (const FamilyScaling& f : analysis.families) families.push_back(family_json(f));
  return json{{"max_exponent_increase", analysis.max_exponent_increase}, {"families", families}};
}

ScalingAnalysis scaling_from_json(const JsonField& field) {
  ScalingAnalysis analysis;
  analysis.max_exponent_increase = number_or_nan(field.member("max_exponent_increase"));
  for (const JsonField& f : field.member("families").elements()) {
    analysis.families.push_back(family_from(f));
  }
  return analysis;
}

}  // namespace raygate

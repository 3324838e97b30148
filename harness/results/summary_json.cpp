#include "results/summary_json.h"

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "results/json_number.h"
#include "results/json_record.h"

namespace raygate {

using nlohmann::json;
using json_record::finite_numbers;
using json_record::number_at;
using json_record::read_numbers;

void to_json(json& j, const Interval& interval) {
  j = json{{"lower", finite_number(interval.lower)}, {"upper", finite_number(interval.upper)}};
}
// A bound written as null was not finite: the interval is unbounded on that side. Read as 0 it
// would say the opposite (an upper bound of +inf read back as 0 put lower above upper; found by
// fuzzing the round trip, tests/fuzz/corpus/results/found-null-upper.json).
void from_json(const json& j, Interval& interval) {
  interval.lower = number_at(j, "lower", -std::numeric_limits<double>::infinity());
  interval.upper = number_at(j, "upper", std::numeric_limits<double>::infinity());
}

void to_json(json& j, const RatioSummary& r) {
  j = finite_numbers({{"normalized_ratio", r.ratio},
                      {"relative_half_width", r.relative_half_width},
                      {"log_ratio_median", r.log_ratio_median},
                      {"log_ratio_mad_scaled", r.log_ratio_mad_scaled},
                      {"tracer_median_seconds", r.tracer_median_seconds},
                      {"baseline_median_seconds", r.baseline_median_seconds}});
  j["rounds"] = r.rounds;
  j["ratio_interval"] = r.ratio_interval;
}
void from_json(const json& j, RatioSummary& r) {
  r.rounds = j.at("rounds").get<std::size_t>();
  r.ratio_interval = j.at("ratio_interval").get<Interval>();
  read_numbers(j, {{"normalized_ratio", &r.ratio},
                   {"relative_half_width", &r.relative_half_width},
                   {"log_ratio_median", &r.log_ratio_median},
                   {"log_ratio_mad_scaled", &r.log_ratio_mad_scaled},
                   {"tracer_median_seconds", &r.tracer_median_seconds},
                   {"baseline_median_seconds", &r.baseline_median_seconds}});
}

void to_json(json& j, const SuiteScore& s) {
  j = json{{"scenes", s.scenes}, {"score", finite_number(s.score)}, {"interval", s.interval}};
}
void from_json(const json& j, SuiteScore& s) {
  s.scenes = j.at("scenes").get<std::size_t>();
  s.score = number_at(j, "score");
  s.interval = j.at("interval").get<Interval>();
}

void to_json(json& j, const ChangeSummary& c) {
  j = json{{"rounds", c.rounds},
           {"change", finite_number(c.change)},
           {"change_interval", c.change_interval},
           {"confidence", finite_number(c.confidence)},
           {"interval_kind", std::string(to_string(c.interval_kind))},
           {"log_change_median", finite_number(c.log_change_median)},
           {"log_change_mad_scaled", finite_number(c.log_change_mad_scaled)},
           {"base", c.base},
           {"head", c.head},
           {"mann_whitney",
            {{"u", finite_number(c.mann_whitney.u)},
             {"z", finite_number(c.mann_whitney.z)},
             {"p_value", finite_number(c.mann_whitney.p_value)}}}};
  if (c.exact) j["exact"] = true;  // --timing sim with identical counts: no interval needed
  if (c.interval_kind == ChangeIntervalKind::confidence_sequence) {
    j["equivalence_interval"] = c.equivalence_interval;
    j["equivalence_confidence"] = finite_number(c.equivalence_confidence);
    j["one_look_interval"] = c.one_look_interval;
    j["one_look_confidence"] = finite_number(c.one_look_confidence);
  }
}
void from_json(const json& j, ChangeSummary& c) {
  c.rounds = j.at("rounds").get<std::size_t>();
  c.change = number_at(j, "change");
  c.change_interval = j.at("change_interval").get<Interval>();
  c.confidence = j.value("confidence", 0.95);  // documents before it was recorded: 95%
  // Documents before the confidence sequence carried the one-look interval.
  const std::string kind = j.value("interval_kind", std::string("order-statistic"));
  const std::optional<ChangeIntervalKind> parsed = change_interval_kind(kind);
  if (!parsed) {
    throw std::invalid_argument("change.interval_kind: unknown interval \"" + kind +
                                "\" (order-statistic or confidence-sequence)");
  }
  c.interval_kind = *parsed;
  if (c.interval_kind == ChangeIntervalKind::confidence_sequence) {
    c.equivalence_interval = j.at("equivalence_interval").get<Interval>();
    c.equivalence_confidence = number_at(j, "equivalence_confidence");
    c.one_look_interval = j.at("one_look_interval").get<Interval>();
    c.one_look_confidence = number_at(j, "one_look_confidence");
  }
  c.log_change_median = number_at(j, "log_change_median");
  c.log_change_mad_scaled = number_at(j, "log_change_mad_scaled");
  c.base = j.at("base").get<RatioSummary>();
  c.head = j.at("head").get<RatioSummary>();
  const json& mw = j.at("mann_whitney");
  c.mann_whitney = {number_at(mw, "u"), number_at(mw, "z"), number_at(mw, "p_value", 1.0)};
  c.exact = j.value("exact", false);
}

void to_json(json& j, const ImageMetrics& m) {
  j = json{{"size_mismatch", m.size_mismatch},
           {"width", m.width},
           {"height", m.height},
           {"expected_width", m.expected_width},
           {"expected_height", m.expected_height},
           {"mean_error", finite_number(m.mean_error)},
           {"rms_error", finite_number(m.rms_error)},
           {"psnr_db", finite_number(m.psnr_db)},  // null: identical images (infinite PSNR)
           {"max_error", finite_number(m.max_error)},
           {"max_pixel", {m.max_x, m.max_y, m.max_channel}},
           {"max_actual_value", finite_number(m.max_actual_value)},
           {"max_expected_value", finite_number(m.max_expected_value)},
           {"pixels_over_warn", m.pixels_over_warn},
           {"pixels_over_fail", m.pixels_over_fail},
           {"percent_over_fail", finite_number(m.percent_over_fail)},
           {"mean_luminance_actual", finite_number(m.mean_luminance_actual)},
           {"mean_luminance_expected", finite_number(m.mean_luminance_expected)},
           {"nonfinite_values", m.nonfinite_values},
           {"nonfinite_pixels", m.nonfinite_pixels},
           {"first_nonfinite_pixel", {m.nonfinite_x, m.nonfinite_y}},
           {"expected_nonfinite_pixels", m.expected_nonfinite_pixels}};
}
void from_json(const json& j, ImageMetrics& m) {
  m.size_mismatch = j.at("size_mismatch").get<bool>();
  m.width = j.at("width").get<int>();
  m.height = j.at("height").get<int>();
  m.expected_width = j.at("expected_width").get<int>();
  m.expected_height = j.at("expected_height").get<int>();
  m.mean_error = number_at(j, "mean_error");
  m.rms_error = number_at(j, "rms_error");
  m.psnr_db = number_at(j, "psnr_db", std::numeric_limits<double>::infinity());
  m.max_error = number_at(j, "max_error");
  const json& pixel = j.at("max_pixel");
  m.max_x = pixel.at(0).get<int>();
  m.max_y = pixel.at(1).get<int>();
  m.max_channel = pixel.at(2).get<int>();
  m.max_actual_value = number_at(j, "max_actual_value");
  m.max_expected_value = number_at(j, "max_expected_value");
  m.pixels_over_warn = j.at("pixels_over_warn").get<long>();
  m.pixels_over_fail = j.at("pixels_over_fail").get<long>();
  m.percent_over_fail = number_at(j, "percent_over_fail");
  m.mean_luminance_actual = number_at(j, "mean_luminance_actual");
  m.mean_luminance_expected = number_at(j, "mean_luminance_expected");
  m.nonfinite_values = j.at("nonfinite_values").get<long>();
  // Absent from documents written before NaN pixels were counted.
  m.nonfinite_pixels = j.value("nonfinite_pixels", 0L);
  const json first = j.value("first_nonfinite_pixel", json::array({0, 0}));
  m.nonfinite_x = first.at(0).get<int>();
  m.nonfinite_y = first.at(1).get<int>();
  m.expected_nonfinite_pixels = j.value("expected_nonfinite_pixels", 0L);
}

namespace {

json change_json(const RelativeChange& c) {
  return finite_numbers({{"change", c.change}, {"low", c.low}, {"high", c.high}});
}
RelativeChange change_from(const json& j) {
  return {number_at(j, "change"), number_at(j, "low"), number_at(j, "high")};
}

json biased_json(const BiasedTile& t) {
  json j = finite_numbers({{"min_effect", t.min_effect}, {"z", t.z}, {"p_value", t.p_value}});
  j["tile_px"] = t.tile_px;  // 0: the whole image
  j["rect"] = {t.rect.x, t.rect.y, t.rect.width, t.rect.height};
  j["channel"] = t.channel;
  j["change"] = change_json(t.change);
  return j;
}
BiasedTile biased_from(const json& j) {
  const json& r = j.at("rect");
  // z is infinite (null) when neither side had noise and still they differ: the change's sign.
  const RelativeChange change = change_from(j.at("change"));
  const double z = j.at("z").is_null()
                       ? std::copysign(std::numeric_limits<double>::infinity(), change.change)
                       : j.at("z").get<double>();
  return {j.at("tile_px").get<int>(),
          {r.at(0).get<int>(), r.at(1).get<int>(), r.at(2).get<int>(), r.at(3).get<int>()},
          j.at("channel").get<int>(),
          change,
          number_at(j, "min_effect"),
          z,
          number_at(j, "p_value")};
}

}  // namespace

void to_json(json& j, const NoisyComparison& c) {
  j = finite_numbers({{"tolerance", c.tolerance},
                      {"confidence", c.confidence},
                      {"samples_factor", c.samples_factor}});  // null: no number of runs
  j["verdict"] = std::string(to_string(c.verdict));
  j["width"] = c.width;
  j["height"] = c.height;
  j["actual_runs"] = c.actual_runs;
  j["expected_runs"] = c.expected_runs;
  j["size_mismatch"] = c.size_mismatch ? json(*c.size_mismatch) : json(nullptr);
  j["tests"] = c.tests;
  j["biased_count"] = c.biased_count;
  j["biased"] = json::array();
  for (const BiasedTile& t : c.biased) j["biased"].push_back(biased_json(t));
  j["image"] = change_json(c.image);
  j["channels"] = json::array();
  for (const RelativeChange& channel : c.channels) j["channels"].push_back(change_json(channel));
  j["scales"] = json::array();
  for (const ScaleReport& s : c.scales) {
    j["scales"].push_back(
        {{"tile_px", s.tile_px}, {"tiles", s.tiles}, {"detectable", finite_number(s.detectable)}});
  }
  j["runs_needed"] = c.runs_needed;
  j["why_inconclusive"] = c.why_inconclusive;
}

void from_json(const json& j, NoisyComparison& c) {
  c.verdict =
      parse_noisy_verdict(j.at("verdict").get<std::string>()).value_or(NoisyVerdict::inconclusive);
  c.tolerance = number_at(j, "tolerance");
  c.confidence = number_at(j, "confidence");
  c.samples_factor = number_at(j, "samples_factor", std::numeric_limits<double>::infinity());
  c.width = j.at("width").get<int>();
  c.height = j.at("height").get<int>();
  c.actual_runs = j.at("actual_runs").get<int>();
  c.expected_runs = j.at("expected_runs").get<int>();
  if (!j.at("size_mismatch").is_null()) c.size_mismatch = j.at("size_mismatch").get<std::string>();
  c.tests = j.at("tests").get<std::size_t>();
  c.biased_count = j.at("biased_count").get<std::size_t>();
  for (const json& t : j.at("biased")) c.biased.push_back(biased_from(t));
  c.image = change_from(j.at("image"));
  for (std::size_t i = 0; i < c.channels.size(); ++i)
    c.channels[i] = change_from(j.at("channels").at(i));
  for (const json& s : j.at("scales")) {
    c.scales.push_back(
        {s.at("tile_px").get<int>(), s.at("tiles").get<std::size_t>(), number_at(s, "detectable")});
  }
  c.runs_needed = j.at("runs_needed").get<int>();
  c.why_inconclusive = j.at("why_inconclusive").get<std::string>();
}

}  // namespace raygate

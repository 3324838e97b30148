#include "results/results_check.h"

#include <fmt/core.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <limits>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "compare/image_check.h"
#include "compare/noisy_image_compare.h"
#include "measure/change.h"
#include "core/domain.h"
#include "core/error.h"
#include "core/memory_cgroup.h"
#include "core/path_component.h"
#include "core/time_text.h"
#include "results/shard.h"
#include "core/json_field.h"
#include "runner/timing/timing_check.h"
#include "runner/timing/timing_modes.h"

namespace raygate {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A second count of a week; no run, scene or build of a CI harness lasts longer, and a larger
// number in a document is a forgery or a corruption that would skew every sum it enters.
constexpr double kMaxSeconds = 7.0 * 24 * 3600;
// The measure a ratio divides: seconds, or under --timing sim estimated cycles
// (runner/cachegrind.h), which for a week of runs at 5 GHz reach 3e15.
constexpr double kMaxMeasure = 1e18;
constexpr std::int64_t kMaxCount = std::int64_t{1} << 40;
constexpr std::int64_t kMaxSceneSize = 1000000;
constexpr std::int64_t kMaxSide = 1 << 20;  // pixels: past any image a tracer writes
constexpr double kMaxLog = 50.0;            // |ln ratio|: a factor of 5e21

// Typed access over core/json_field.h's path-carrying reader, with the ranges a measured
// document's numbers must be in.
const JsonField& object(const JsonField& field) {
  if (!field.value().is_object()) {
    field.fail("expected an object, found " + describe_json(field.value()));
  }
  return field;
}

const JsonField& array(const JsonField& field) {
  if (!field.value().is_array()) {
    field.fail("expected an array, found " + describe_json(field.value()));
  }
  return field;
}

std::optional<JsonField> find(const JsonField& field, std::string_view key) {
  object(field);
  if (!field.has(key)) return std::nullopt;
  return field.member(key);
}

std::optional<JsonField> find_non_null(const JsonField& field, std::string_view key) {
  std::optional<JsonField> found = find(field, key);
  if (found && found->value().is_null()) return std::nullopt;
  return found;
}

double number(const JsonField& field, double lowest, double highest) {
  const double v = field.as_number();
  if (!std::isfinite(v)) field.fail("expected a finite number");
  if (v < lowest || v > highest) {
    field.fail(
        fmt::format("{} is out of range (from {} to {})", field.value().dump(), lowest, highest));
  }
  return v;
}

// The document writes a number that is not finite as null.
std::optional<double> number_or_null(const JsonField& field, double lowest, double highest) {
  if (field.value().is_null()) return std::nullopt;
  return number(field, lowest, highest);
}

std::int64_t integer(const JsonField& field, std::int64_t lowest, std::int64_t highest) {
  const nlohmann::json& v = field.value();
  if (!v.is_number_integer()) field.fail("expected a whole number, found " + describe_json(v));
  const bool above = v.is_number_unsigned()
                         ? v.get<std::uint64_t>() > static_cast<std::uint64_t>(highest)
                         : v.get<std::int64_t>() > highest;
  if (above || (!v.is_number_unsigned() && v.get<std::int64_t>() < lowest)) {
    field.fail(fmt::format("{} is out of range (from {} to {})", v.dump(), lowest, highest));
  }
  return v.get<std::int64_t>();
}

// A counter of cachegrind's: any whole number a uint64 holds.
void counter(const JsonField& field) {
  const nlohmann::json& v = field.value();
  if (v.is_number_unsigned() || (v.is_number_integer() && v.get<std::int64_t>() >= 0)) return;
  if (v.is_number_integer()) field.fail(fmt::format("{} must not be negative", v.dump()));
  field.fail("expected a whole number, found " + describe_json(v));
}

void require_word(const JsonField& field, std::string_view word,
                  std::initializer_list<std::string_view> known) {
  for (const std::string_view k : known) {
    if (word == k) return;
  }
  std::string list;
  for (const std::string_view k : known) {
    // An allowed empty word is shown as one, not as a trailing ", ".
    list += (list.empty() ? "" : ", ") + (k.empty() ? std::string("\"\"") : std::string(k));
  }
  field.fail(fmt::format("unknown value \"{}\" (one of: {})", word, list));
}

std::string word_at(const JsonField& parent, std::string_view key,
                    std::initializer_list<std::string_view> known) {
  const JsonField field = parent.member(key);
  const std::string word = field.as_string();
  require_word(field, word, known);
  return word;
}

// The word read as its Role (core/domain.h), which must be one of `roles`.
void require_role(const JsonField& field, const std::string& word, const std::set<Role>& roles) {
  const std::optional<Role> role = parse_role(word);
  if (!role || roles.count(*role) == 0) field.fail(fmt::format("unknown role \"{}\"", word));
}

void check_strings(const JsonField& object, std::initializer_list<std::string_view> keys) {
  for (const std::string_view key : keys) object.member(key).as_string();
}

// A time as raygate writes one (core/time_text.h), "2026-11-29T14:37:00Z", or "" for none. merge
// keeps the earliest start by comparing the text and history orders by it: "yesterday" would sort.
void check_timestamps(const JsonField& object, std::initializer_list<std::string_view> keys) {
  for (const std::string_view key : keys) {
    const JsonField field = object.member(key);
    const std::string text = field.as_string();
    if (!text.empty() && !is_iso8601_time(text)) {
      field.fail(fmt::format("\"{}\" is not an ISO 8601 time such as 2026-11-29T14:37:00Z",
                             text.substr(0, 40)));
    }
  }
}

// "" (no shard) or "K/N" with 1 <= K <= N, as --shard takes it: reports print it as it reads.
void check_shard_label(const JsonField& shard) {
  const std::string label = shard.as_string();
  if (label.empty()) return;
  try {
    parse_shard(label);
  } catch (const UsageError&) {
    shard.fail(fmt::format("\"{}\" is not a shard K/N with 1 <= K <= N", label.substr(0, 40)));
  }
}

// The top-level label is the store's index of settings.shard, which merge reads: the two name
// one shard (the tenth sweep merged and gated a 1/2 labelled 2/2).
void check_shard_agrees(const JsonField& shard, const JsonField& settings) {
  if (shard.as_string().empty() || !settings.value().is_object() || !settings.has("shard")) return;
  const nlohmann::json& record = settings.member("shard").value();
  if (!record.is_object() || !record.contains("index") || !record.contains("count") ||
      !record["index"].is_number_integer() || !record["count"].is_number_integer()) {
    return;  // settings_json says what is wrong with it, at its path
  }
  const std::string recorded = fmt::format("{}/{}", record["index"].get<std::int64_t>(),
                                           record["count"].get<std::int64_t>());
  if (shard.as_string() != recorded) {
    shard.fail(
        fmt::format("\"{}\", but settings.shard is {}", shard.as_string().substr(0, 40), recorded));
  }
}

// merge orders shards and history orders runs by these times: a run cannot finish before it began.
void check_started_before_finished(const JsonField& document) {
  const auto started = iso8601_epoch_seconds(document.member("started_at").as_string());
  const auto finished = iso8601_epoch_seconds(document.member("finished_at").as_string());
  if (started && finished && *finished < *started) {
    document.member("finished_at")
        .fail(fmt::format("\"{}\" is before started_at \"{}\"",
                          document.member("finished_at").as_string().substr(0, 40),
                          document.member("started_at").as_string().substr(0, 40)));
  }
}

void check_seconds(const JsonField& object, std::initializer_list<std::string_view> keys) {
  for (const std::string_view key : keys) number(object.member(key), 0.0, kMaxSeconds);
}

// The interval's ends as checked (null: no end).
std::pair<std::optional<double>, std::optional<double>> check_interval(const JsonField& field,
                                                                       double lowest,
                                                                       double highest) {
  object(field);
  const auto lower = number_or_null(field.member("lower"), lowest, highest);
  const auto upper = number_or_null(field.member("upper"), lowest, highest);
  if (lower && upper && *lower > *upper) field.fail("lower is above upper");
  return {lower, upper};
}

void check_run(const JsonField& run) {
  object(run);
  const bool ok = run.member("ok").as_bool();
  check_strings(run, {"outcome", "image", "log"});
  // The gate calls head's failure no regression when it is set: on a run that ran well, a hand
  // edit; written only when true.
  if (const auto budget = find(run, "stopped_by_budget"); budget && budget->as_bool() && ok) {
    budget->fail("a run stopped by the budget did not succeed (ok is true)");
  }
  if (const auto failure = find(run, "failure")) failure->as_string();
  number(run.member("seconds"), 0.0, kMaxMeasure);
  check_seconds(run, {"wall_seconds", "user_seconds", "system_seconds"});
  integer(run.member("max_rss_kib"), 0, kMaxCount);
  if (const auto own = find(run, "max_rss_own")) own->as_bool();
  if (const auto method = find(run, "peak_method")) {
    // The words come from the one table the writer uses (core/memory_cgroup.cpp).
    if (!parse_peak_method(method->as_string())) {
      require_word(*method, method->as_string(),
                   {"raygate-process", "largest-process", "cgroup-v1", "cgroup-v2"});
    }
  }
  number_or_null(run.member("reported_seconds"), 0.0, kMaxMeasure);
  if (const auto counters = find(run, "cachegrind")) {
    object(*counters);
    for (const char* key : {"Ir", "I1mr", "ILmr", "Dr", "D1mr", "DLmr", "Dw", "D1mw", "DLmw"}) {
      counter(counters->member(key));
    }
    if (const auto processes = find(*counters, "processes")) integer(*processes, 1, kMaxCount);
  }
}

void check_runs_by_role(const JsonField& runs, const std::set<Role>& roles) {
  for (const std::string& role : object(runs).keys()) {
    const JsonField field = runs.member(role);
    require_role(field, role, roles);
    check_run(field);
  }
}

void check_ratio(const JsonField& r) {
  object(r);
  const std::int64_t rounds = integer(r.member("rounds"), 0, kMaxCount);
  // Null is a ratio of no rounds: read back as 0, one with rounds would print as 0.000 beside
  // its own interval.
  // At most kMaxMeasure, as the store checks what it reads back: 1e308 was imported, and every
  // later history then called the store damaged (a sweep).
  const auto ratio = number_or_null(r.member("normalized_ratio"), 0.0, kMaxMeasure);
  if (!ratio && rounds > 0) {
    r.member("normalized_ratio").fail(fmt::format("is null, but {} rounds measured it", rounds));
  }
  // A ratio of two measured times is above 0 (0 would be printed "+-inf%" and trended as a
  // thousandfold speed-up) and inside the interval drawn around it from the same rounds.
  if (ratio && *ratio == 0.0 && rounds > 0) {
    r.member("normalized_ratio").fail("is 0: a ratio of two measured times is above 0");
  }
  const auto [lower, upper] = check_interval(r.member("ratio_interval"), 0.0, kMaxMeasure);
  const double slack = 1e-9 * (1.0 + (ratio ? *ratio : 0.0));  // printed and read as decimals
  if (ratio && lower && upper && (*ratio < *lower - slack || *ratio > *upper + slack)) {
    r.member("normalized_ratio")
        .fail(fmt::format("{} lies outside its ratio_interval [{}, {}]", *ratio, *lower, *upper));
  }
  number_or_null(r.member("relative_half_width"), 0.0, kInf);
  number_or_null(r.member("log_ratio_median"), -kMaxLog, kMaxLog);
  number_or_null(r.member("log_ratio_mad_scaled"), 0.0, kInf);
  number_or_null(r.member("tracer_median_seconds"), 0.0, kMaxMeasure);
  number_or_null(r.member("baseline_median_seconds"), 0.0, kMaxMeasure);
}

// The median change lies inside every interval raygate draws around it from the same rounds: a
// change outside its own interval was written by hand, and the gate would judge it as it reads.
void check_change_in_interval(const JsonField& field, std::optional<double> change,
                              const JsonField& interval) {
  const auto [lower, upper] = check_interval(interval, -1.0, kInf);
  if (!change || !lower || !upper) return;
  const double slack = 1e-9 * (1.0 + std::abs(*change));  // printed and read back as decimals
  if (*change < *lower - slack || *change > *upper + slack) {
    field.fail(
        fmt::format("{} lies outside its change_interval [{}, {}]", *change, *lower, *upper));
  }
}

void check_verdict(const JsonField& verdict) {
  const std::string word = verdict.as_string();
  if (!change_verdict_named(word)) {
    require_word(verdict, word, {"UNCHANGED", "IMPROVED", "REGRESSED", "INCONCLUSIVE"});
  }
}

// A level the gate judges at again: 0 and 1 leave no error to spend (the sweep's 0 ended in an
// internal error where the confidence sequence was drawn).
void confidence_level(const JsonField& field) {
  const double level = number(field, 0.0, 1.0);
  if (level == 0.0 || level == 1.0)
    field.fail(fmt::format("{} is not a confidence level: one lies strictly between 0 and 1",
                           field.value().dump()));
}

void confidence_level_or_null(const JsonField& field) {
  if (!field.value().is_null()) confidence_level(field);
}

// `scene_rounds`: the rounds the scene lists, of which the change's are some (a forged 50 beside
// 3 listed decided the gate, the eleventh sweep).
void check_change(const JsonField& c, std::size_t scene_rounds) {
  object(c);
  const std::int64_t rounds = integer(c.member("rounds"), 0, kMaxCount);
  // A document without its rounds (a summary built in memory) says nothing to check against.
  if (scene_rounds > 0 && static_cast<std::size_t>(rounds) > scene_rounds) {
    c.member("rounds").fail(fmt::format("{} rounds, but the scene lists {}", rounds, scene_rounds));
  }
  const auto change = number_or_null(c.member("change"), -1.0, kInf);  // head / base - 1
  // A change is null only where no round measured one; the gate reads a null as +0% and judged
  // [+881.7%, +1714.9%] beside it INCONCLUSIVE (the tenth sweep).
  const JsonField interval = c.member("change_interval");
  if (!change && interval.value().is_object() && interval.has("lower") &&
      !interval.member("lower").value().is_null()) {
    c.member("change").fail("is null, but its change_interval is not");
  }
  if (change && rounds == 0) c.member("rounds").fail("0 rounds, but a change is given");
  check_change_in_interval(c.member("change"), change, interval);
  if (const auto confidence = find(c, "confidence")) confidence_level(*confidence);
  std::string kind = "order-statistic";  // documents from before the confidence sequences
  if (const auto k = find(c, "interval_kind")) {
    kind = k->as_string();
    require_word(*k, kind, {"order-statistic", "confidence-sequence"});
  }
  if (change_interval_kind(kind) == ChangeIntervalKind::confidence_sequence) {
    check_interval(c.member("equivalence_interval"), -1.0, kInf);
    confidence_level_or_null(c.member("equivalence_confidence"));
    check_interval(c.member("one_look_interval"), -1.0, kInf);
    confidence_level_or_null(c.member("one_look_confidence"));
  }
  number_or_null(c.member("log_change_median"), -kMaxLog, kMaxLog);
  number_or_null(c.member("log_change_mad_scaled"), 0.0, kInf);
  check_ratio(c.member("base"));
  check_ratio(c.member("head"));
  const JsonField mw = object(c.member("mann_whitney"));
  number_or_null(mw.member("u"), 0.0, kInf);
  number_or_null(mw.member("z"), -kInf, kInf);
  number_or_null(mw.member("p_value"), 0.0, 1.0);
  if (const auto exact = find(c, "exact")) exact->as_bool();
  check_verdict(c.member("verdict"));
}

void check_pixel(const JsonField& field, std::size_t coordinates, const char* shape) {
  const std::vector<JsonField> parts = array(field).elements();
  if (parts.size() != coordinates) field.fail(std::string("expected ") + shape);
  for (const JsonField& part : parts) integer(part, 0, kMaxSide);
}

void check_metrics(const JsonField& m) {
  object(m);
  m.member("size_mismatch").as_bool();
  for (const char* key : {"width", "height", "expected_width", "expected_height"}) {
    integer(m.member(key), 0, kMaxSide);
  }
  for (const char* key : {"mean_error", "rms_error", "max_error"}) {
    number_or_null(m.member(key), 0.0, kInf);
  }
  for (const char* key : {"psnr_db", "max_actual_value", "max_expected_value",
                          "mean_luminance_actual", "mean_luminance_expected"}) {
    number_or_null(m.member(key), -kInf, kInf);
  }
  check_pixel(m.member("max_pixel"), 3, "[x, y, channel]");
  for (const char* key : {"pixels_over_warn", "pixels_over_fail", "nonfinite_values"}) {
    integer(m.member(key), 0, kMaxCount);
  }
  number_or_null(m.member("percent_over_fail"), 0.0, 100.0);
  for (const char* key : {"nonfinite_pixels", "expected_nonfinite_pixels"}) {
    if (const auto count = find(m, key)) integer(*count, 0, kMaxCount);
  }
  if (const auto first = find(m, "first_nonfinite_pixel")) check_pixel(*first, 2, "[x, y]");
}

// A comparison's verdict where its own metrics rule it out, whatever the thresholds were: a
// failure of identical images, a pass of images of two sizes or with NaN (the eleventh sweep's
// forged "fail … identical" exited 1).
void check_verdict_against_metrics(const JsonField& verdict, const JsonField& m) {
  const std::string word = verdict.as_string();
  const bool mismatch = m.member("size_mismatch").as_bool();
  const bool nonfinite = m.member("nonfinite_values").value() != 0;
  const nlohmann::json& max_error = m.member("max_error").value();
  const bool identical = !mismatch && !nonfinite && max_error.is_number() &&
                         max_error.get<double>() == 0.0 &&
                         m.member("pixels_over_warn").value() == 0;
  if ((word == "fail" || word == "warn") && identical) {
    verdict.fail(fmt::format("\"{}\", but its metrics say the images are identical", word));
  }
  if (word == "pass" && (mismatch || nonfinite)) {
    verdict.fail(mismatch ? "\"pass\", but its metrics say the sizes differ"
                          : "\"pass\", but its metrics count NaN or Inf values");
  }
}

// A relative change: finite (against a black reference it can be huge, never infinite).
RelativeChange check_relative_change(const JsonField& field) {
  object(field);
  constexpr double kMaxRelative = 1e300;
  const double change = number(field.member("change"), -kMaxRelative, kMaxRelative);
  const double low = number(field.member("low"), -kMaxRelative, kMaxRelative);
  const double high = number(field.member("high"), -kMaxRelative, kMaxRelative);
  if (low > change || change > high) field.fail("expected low <= change <= high");
  return {change, low, high};
}

void check_biased_tile(const JsonField& tile) {
  object(tile);
  integer(tile.member("tile_px"), 0, kMaxSide);
  const JsonField rect = array(tile.member("rect"));
  if (rect.value().size() != 4) rect.fail("expected [x, y, width, height]");
  for (const JsonField& n : rect.elements()) integer(n, 0, kMaxSide);
  integer(tile.member("channel"), 0, 2);
  check_relative_change(tile.member("change"));
  number(tile.member("min_effect"), 0.0, 1e300);
  number_or_null(tile.member("z"), -kInf, kInf);
  number(tile.member("p_value"), 0.0, 1.0);
}

// A Monte Carlo comparison (images[].monte_carlo): its words, ranges, and that its verdict is
// what its numbers say: a pass whose interval reaches beyond the tolerance is refused.
NoisyVerdict check_noisy(const JsonField& mc) {
  object(mc);
  const JsonField verdict_field = mc.member("verdict");
  const std::string word = verdict_field.as_string();
  const std::optional<NoisyVerdict> verdict = parse_noisy_verdict(word);
  if (!verdict) require_word(verdict_field, word, {"pass", "fail", "inconclusive"});
  const double tolerance = number(mc.member("tolerance"), 1e-6, 1.0);
  number(mc.member("confidence"), 0.5, 1.0 - 1e-12);
  for (const char* key : {"width", "height"}) integer(mc.member(key), 0, kMaxSide);
  for (const char* key : {"actual_runs", "expected_runs", "runs_needed"}) {
    integer(mc.member(key), 0, kMaxCount);
  }
  if (const auto mismatch = find_non_null(mc, "size_mismatch")) mismatch->as_string();
  integer(mc.member("tests"), 0, kMaxCount);
  const std::int64_t biased = integer(mc.member("biased_count"), 0, kMaxCount);
  const JsonField tiles = array(mc.member("biased"));
  if (static_cast<std::int64_t>(tiles.value().size()) > biased)
    tiles.fail("more tiles than biased_count");
  for (const JsonField& tile : tiles.elements()) check_biased_tile(tile);
  std::vector<RelativeChange> intervals{check_relative_change(mc.member("image"))};
  const JsonField channels = array(mc.member("channels"));
  if (channels.value().size() != 3) channels.fail("expected 3 channels (R, G, B)");
  for (const JsonField& c : channels.elements()) intervals.push_back(check_relative_change(c));
  for (const JsonField& s : array(mc.member("scales")).elements()) {
    integer(s.member("tile_px"), 0, kMaxSide);
    integer(s.member("tiles"), 0, kMaxCount);
    number_or_null(s.member("detectable"), 0.0, kInf);
  }
  number_or_null(mc.member("samples_factor"), 1.0, kInf);  // null: no number of runs decides
  mc.member("why_inconclusive").as_string();
  if (*verdict == NoisyVerdict::pass) {
    for (const RelativeChange& c : intervals) {
      if (c.low < -tolerance || c.high > tolerance) {
        verdict_field.fail(
            fmt::format("\"pass\" with an interval [{}, {}] beyond the tolerance "
                        "±{}",
                        c.low, c.high, tolerance));
      }
    }
    if (biased > 0) verdict_field.fail("\"pass\" with biased tiles");
  }
  return *verdict;
}

void check_image(const JsonField& image, const std::set<Role>& roles) {
  object(image);
  const JsonField role = image.member("role");
  require_role(role, role.as_string(), roles);
  check_strings(image, {"reference", "actual", "expected"});
  require_word(image.member("reference"), image.member("reference").as_string(),
               {"golden", "base"});
  const JsonField verdict = image.member("verdict");
  if (!parse_image_verdict(verdict.as_string())) {
    require_word(verdict, verdict.as_string(),
                 {"pass", "warn", "inconclusive", "fail", "missing", "error"});
  }
  if (const auto mc = find(image, "monte_carlo")) {
    const NoisyVerdict noisy = check_noisy(*mc);
    if (to_string(noisy) != verdict.as_string()) {
      verdict.fail(fmt::format("\"{}\", but monte_carlo.verdict is \"{}\"", verdict.as_string(),
                               to_string(noisy)));
    }
  }
  if (const auto error = find(image, "error")) error->as_string();
  image.member("metrics");  // required, even when null
  if (const auto metrics = find_non_null(image, "metrics")) {
    check_metrics(*metrics);
    if (!find(image, "monte_carlo")) check_verdict_against_metrics(verdict, *metrics);
  }
  for (const JsonField& path : array(image.member("evidence")).elements()) path.as_string();
}

void check_scene_entry(const JsonField& entry) {
  object(entry);
  check_strings(entry, {"id", "scene"});
  // An SPD size (each generator says its own maximum, 10 or less); read into an int.
  integer(entry.member("size"), 0, kMaxSceneSize);
  integer(entry.member("width"), 1, kMaxSide);
  integer(entry.member("height"), 1, kMaxSide);
}

// The roles a document's parts may name: a revision's (tracer in run, base and head in compare)
// and, for runs, the baseline's too. Any of the words, not only the document's own revisions:
// documents merged or written by older versions mix them, and a word raygate does not know is
// what would mislead a reader.
// The roles a document of its kind measures: a run the tracer, a compare base and head, both
// beside the baseline. A run carrying head's ratios or a change was hand-made, and each reader
// would pick what it looks for out of it.
struct Roles {
  std::set<Role> revisions;
  std::set<Role> runs;
};

Roles roles_of(const std::string& kind) {
  if (kind == "run") return {{Role::tracer}, {Role::tracer, Role::baseline}};
  return {{Role::base, Role::head}, {Role::base, Role::head, Role::baseline}};
}

void check_rounds(const JsonField& rounds, const Roles& roles) {
  for (const JsonField& round : array(rounds).elements()) {
    object(round);
    for (const JsonField& role : array(round.member("order")).elements()) {
      require_role(role, role.as_string(), roles.runs);
    }
    check_runs_by_role(round.member("runs"), roles.runs);
  }
}

void check_scene(const JsonField& s, const Roles& roles) {
  object(s);
  check_scene_entry(s.member("scene"));
  s.member("scene_sha256").as_string();
  const JsonField status = s.member("status");
  word_at(s, "status", {"measured", "failed"});
  // A failed scene names its failed run, and only a failed one does: the gate judges the failure.
  if ((status.as_string() == "failed") != find_non_null(s, "failure").has_value()) {
    status.fail(status.as_string() == "failed" ? "\"failed\" with no failure (null)"
                                               : "\"measured\" with a failure");
  }
  // "": no rounds were run (a warm-up only), so nothing stopped them.
  word_at(s, "stop_reason",
          {"stop_converged", "stop_budget_rounds", "stop_budget_time", "failed", "continue", ""});
  number_or_null(s.member("seconds_spent"), 0.0, kMaxSeconds);
  s.member("failure");  // required, even when null
  if (const auto failure = find_non_null(s, "failure")) {
    object(*failure);
    const JsonField role = failure->member("role");
    require_role(role, role.as_string(), roles.runs);
    check_run(failure->member("run"));
  }
  const JsonField warmup = object(s.member("warmup"));
  for (const std::string& role : warmup.keys()) {
    const JsonField runs = warmup.member(role);
    require_role(runs, role, roles.runs);
    for (const JsonField& run : array(runs).elements()) check_run(run);
  }
  check_rounds(s.member("rounds"), roles);
  if (const auto partial = find(s, "partial_round")) check_runs_by_role(*partial, roles.runs);
  const JsonField ratios = object(s.member("ratios"));
  for (const std::string& role : ratios.keys()) {
    require_role(ratios.member(role), role, roles.revisions);
    check_ratio(ratios.member(role));
  }
  s.member("change");  // required, even when null
  if (const auto change = find_non_null(s, "change")) {
    if (roles.revisions.count(Role::head) == 0) change->fail("a run document has no change");
    check_change(*change, array(s.member("rounds")).elements().size());
  }
  for (const JsonField& image : array(s.member("images")).elements()) {
    check_image(image, roles.revisions);
  }
}

void check_build(const JsonField& b) {
  object(b);
  integer(b.member("record_version"), 1, 1);
  check_strings(b, {"sha", "adapter_name", "adapter_hash", "compiler", "key", "build_dir",
                    "src_dir", "failure", "log_tail"});
  for (const char* key : {"dirty", "cached", "success"}) b.member(key).as_bool();
  number(b.member("total_seconds"), 0.0, kMaxSeconds);
  for (const JsonField& step : array(b.member("steps")).elements()) {
    object(step);
    for (const JsonField& arg : array(step.member("argv")).elements()) arg.as_string();
    check_strings(step, {"outcome", "log"});
    step.member("succeeded").as_bool();
    check_seconds(step, {"wall_seconds", "cpu_seconds"});
  }
}

// What checkout records (checkout/describe.cpp, uncommitted.cpp): a commit's id, 40 hex digits
// (64 in a SHA-256 repository), or "uncommitted". History, consistency and the HTML trend's marks
// match revisions by it, so "zzzz" would match nothing and say nothing.
void check_commit_id(const JsonField& sha) {
  const std::string text = sha.as_string();
  if (text == "uncommitted") return;
  const bool hex = text.find_first_not_of("0123456789abcdef") == std::string::npos;
  if (!hex || (text.size() != 40 && text.size() != 64)) {
    sha.fail(fmt::format("\"{}\" is not a commit id (40 or 64 hex digits) or \"uncommitted\"",
                         text.substr(0, 80)));
  }
}

// The short id names folders (export's runs/<time>-<short_sha>) and is printed for the commit:
// the start of the sha, or "uncommitted" beside it, or nothing (a forged "../../esc" was
// imported, then blocked export of the whole store; a sweep).
void check_short_id(const JsonField& worktree) {
  const std::string sha = worktree.member("sha").as_string();
  const JsonField short_sha = worktree.member("short_sha");
  const std::string text = short_sha.as_string();
  const bool prefix = text.size() >= 4 && sha != "uncommitted" && sha.starts_with(text);
  if (!text.empty() && !prefix && !(sha == "uncommitted" && text == sha)) {
    short_sha.fail(fmt::format("\"{}\" is not the start of sha \"{}\"", text.substr(0, 80),
                               sha.substr(0, 80)));
  }
}

void check_revision(const JsonField& r) {
  object(r);
  check_strings(r, {"repository"});
  if (const auto id = find(r, "repository_id")) id->as_string();
  const JsonField w = object(r.member("worktree"));
  check_strings(w, {"path", "revision", "ref_name", "sha", "short_sha", "subject", "author"});
  check_timestamps(w, {"commit_time"});
  check_commit_id(w.member("sha"));
  check_short_id(w);
  w.member("dirty").as_bool();
  const JsonField adapter = object(r.member("adapter"));
  check_strings(adapter, {"name", "hash", "file"});
  // The name becomes a folder (golden/<adapter>/ of golden bless --from-run): a name that could
  // climb out of it is refused here, as load_adapter refuses it in an adapter file.
  const std::string name = adapter.member("name").as_string();
  if (std::string problem = component_problem(name); !name.empty() && !problem.empty()) {
    adapter.member("name").fail(fmt::format("\"{}\" {}", name.substr(0, 80), problem));
  }
  check_build(r.member("build"));
}

// Each revision once, under a role of the document's kind: a run measures a tracer, a compare
// base and head (a run relabelled "compare" would be judged with no change to judge).
void check_revisions(const JsonField& revisions, const std::string& kind) {
  std::set<std::string> seen;
  for (const JsonField& revision : array(revisions).elements()) {
    check_revision(revision);
    const JsonField role = revision.member("role");
    const std::string word = role.as_string();
    if (kind == "run") {
      require_word(role, word, {"tracer"});
    } else {
      require_word(role, word, {"base", "head"});
    }
    if (!seen.insert(word).second) role.fail(fmt::format("role \"{}\" is listed twice", word));
  }
  const std::size_t expected = kind == "run" ? 1 : 2;
  if (seen.size() != expected) {
    revisions.fail(fmt::format("a {} document records {} revision{} ({}), found {}", kind, expected,
                               expected == 1 ? "" : "s",
                               kind == "run" ? "the tracer" : "base and head", seen.size()));
  }
}

void check_scores(const JsonField& scores, const Roles& roles) {
  for (const std::string& role : object(scores).keys()) {
    const JsonField score = object(scores.member(role));
    require_role(score, role, roles.revisions);
    const std::int64_t scenes = integer(score.member("scenes"), 0, kMaxCount);
    if (!number_or_null(score.member("score"), 0.0, kInf) && scenes > 0) {
      score.member("score").fail(fmt::format("is null, but it scores {} scenes", scenes));
    }
    check_interval(score.member("interval"), 0.0, kInf);
  }
}

// The machine the document says it ran on (measure/machine_context.h): the reports, the store's
// drift rule and consistency read its words and counts. null: not probed (documents built in
// memory); an absent key: a raygate from before it; an unknown key: a newer raygate's.
void check_machine(const JsonField& machine) {
  if (machine.value().is_null()) return;
  object(machine);
  for (const char* key : {"cpu_model", "kernel", "compiler", "perf_error", "hostname"}) {
    if (const auto text = find_non_null(machine, key)) text->as_string();
  }
  for (const char* key : {"logical_cores", "online_cpus", "allowed_cpus"}) {
    if (const auto count = find_non_null(machine, key)) integer(*count, 0, kMaxCount);
  }
  if (const auto paranoid = find_non_null(machine, "perf_event_paranoid")) {
    integer(*paranoid, -1000, 1000);
  }
  if (const auto bytes = find_non_null(machine, "total_memory_bytes")) counter(*bytes);
  for (const char* key : {"turbo_enabled", "perf_instructions_available", "ci"}) {
    if (const auto flag = find_non_null(machine, key)) flag->as_bool();
  }
  if (const auto governors = find(machine, "scaling_governors")) {
    for (const JsonField& governor : array(*governors).elements()) governor.as_string();
  }
  if (const auto load = find_non_null(machine, "load_average")) {
    const std::vector<JsonField> minutes = array(*load).elements();
    if (minutes.size() != 3) load->fail("expected [1, 5, 15] minutes' load");
    for (const JsonField& value : minutes) number(value, 0.0, 1e6);
  }
}

// The settings' shard records of a merged document carry each shard's machine, which the
// reports and consistency read as they read the document's own: checked the same way.
void check_settings(const JsonField& settings) {
  // null: what a document built in memory without settings (tests, tools) wrote before the
  // settings were typed; read as none. The fields are checked as they are read (settings_json).
  if (settings.value().is_null()) return;
  object(settings);
  if (const auto merged = find_non_null(settings, "merged_shards")) {
    for (const JsonField& shard : array(*merged).elements()) {
      if (const auto machine = find(shard, "machine")) check_machine(*machine);
    }
  }
}

}  // namespace

void check_results_json(const nlohmann::json& document, const TimingModeList& modes) {
  const JsonField d(document, "$");
  object(d);
  const std::string kind = word_at(d, "kind", {"run", "compare"});
  check_strings(d, {"raygate_version", "suite"});
  check_timestamps(d, {"started_at", "finished_at"});
  check_started_before_finished(d);
  d.member("complete").as_bool();
  check_machine(d.member("machine"));
  check_settings(d.member("settings"));
  if (const auto shard = find(d, "shard")) {
    check_shard_label(*shard);
    check_shard_agrees(*shard, d.member("settings"));
  }
  const JsonField baseline = object(d.member("baseline"));
  check_strings(baseline, {"version", "source_sha256"});
  word_at(baseline, "accel", {"none", "bbox"});
  word_at(baseline, "sampling", {"center", "corners"});
  check_revisions(d.member("revisions"), kind);
  const Roles roles = roles_of(kind);
  std::set<std::string> ids;
  for (const JsonField& scene : array(d.member("scenes")).elements()) {
    check_scene(scene, roles);
    const JsonField id = scene.member("scene").member("id");
    // A scene id names its run folders and golden files.
    if (std::string problem = component_problem(id.as_string()); !problem.empty()) {
      id.fail(fmt::format("\"{}\" {}", id.as_string().substr(0, 80), problem));
    }
    if (!ids.insert(id.as_string()).second) {
      id.fail(fmt::format("scene \"{}\" is listed twice", id.as_string()));
    }
  }
  check_scores(d.member("scores"), roles);
  // The clock names, the unit and the runs' counters: from the registry the modes come from.
  check_document_timing(d, modes);
}

void check_results_json(const nlohmann::json& document) {
  check_results_json(document, timing_modes());
}

}  // namespace raygate
